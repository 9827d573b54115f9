(O0008 of seed 000 run as finishing pass only, J2: no plunges, the blade traces the trapezoid.)
(IS-C: P30000 is 3 mm, Q50000 is 5 mm.)
O7502;
G99 G00 X60 Z30 M3 S500;
G75.1 X50 Z30 P30000 Q50000 H-20 D-10 A45 B30;
G75.1 R0.5 I4 J2 F0.1;
M30;
