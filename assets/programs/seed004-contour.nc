(seed 004 contour with G42/G40 removed: a sharp 35-degree insert follows the programmed)
(profile itself. One roughing pass at X27 first so the insert can reach the dome's corner.)
O0004;
G00 X100. Z100.
G97 S800 M03
T0101
G00 X40. Z2.
X27.
G01 Z-3.5 F100
G01 X40.
G00 Z10.
X10.
G1 Z0. F80
G03 X30. Z-10. R10
G01 Z-17.639
G02 X32.111 Z-22.111 R10
G01 X33.803 Z-23.803
G03 X35.914 Z-28.275 R14
G01 Z-35.
X50.
G00 X80. Z80.
M09
G00 X100. Z100. T0200
M30
