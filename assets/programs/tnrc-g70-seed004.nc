(seed 004's contour as a G70 finishing shape with G42 in its ns block: G70 runs it)
(compensated - T0101 = 35-degree insert, nose r1, tip 3 - after one roughing pass at X27)
O0070;
G00 X100. Z100.;
G97 S800 M03;
T0101;
G00 X40. Z2.;
X27.;
G01 Z-3.5 F100;
G01 X40.;
G00 X52. Z2.;
G70 P10 Q20;
N10 G42 G01 X10. Z0. F80;
G03 X30. Z-10. R10;
G01 Z-17.639;
G02 X32.111 Z-22.111 R10;
G01 X33.803 Z-23.803;
G03 X35.914 Z-28.275 R14;
G01 Z-35.;
N20 X50.;
G40 G00 X100. Z100.;
M30;
