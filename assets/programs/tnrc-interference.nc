(G42 with a nose radius 1 insert on a contour with a concave R0.5 fillet: the nose cannot)
(follow it - tool nose radius interference, alarm PS041 at line 8, and the overcut it causes)
O0041;
G99 M03 S800 T0101;
G00 X42. Z2.;
G42 G01 X20. Z0. F0.1;
G01 Z-10.;
G02 X21. Z-10.5 R0.5;
G01 X30.;
G01 Z-20.;
G01 X42.;
G40 G00 X50.;
M30;
