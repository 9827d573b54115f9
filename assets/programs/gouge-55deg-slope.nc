(A 55-degree insert descends a 45-degree cone: steeper than its 32-degree trailing edge.)
(Expected: a gouge made at line 7, 11 mm of edge x sin 13 deg = 2.474 mm deep into the cone.)
O0055;
G99 M03 S800 T0101;
G00 X42. Z2.;
G01 X40. Z-5. F0.15;
G01 X20. Z-15.;
G01 Z-25.;
G01 X42.;
G00 Z2.;
M30;
