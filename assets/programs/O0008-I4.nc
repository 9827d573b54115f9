(O0008 of seed 000 with the two things the printed example leaves to the operator: a feed,)
(and the 4 mm blade given to the cycle with I4, so the plunges keep the blade inside the groove.)
(IS-C: P30000 is 3 mm, Q50000 is 5 mm. Groove: P1 Z30 X50, P2 Z20 X30, P3 Z10 X30, P4 Z-7.32 X50.)
O0008;
G99 G00 X60 Z30 M3 S500;
G75.1 X50 Z30 P30000 Q50000 H-20 D-10 A45 B30;
G75.1 R0.5 I4 F0.1;
M30;
