(G75.1 with all four corners broken: a round R1 at the mouth on the start side, a 1.5 chamfer)
(at the mouth on the far side, a 1 chamfer at the floor start, a round R2 at the floor far side.)
(P1 Z0 X60, floor X44 from Z0 to Z-12, far flank at 60 deg; three layers of V6; rough + finish;)
(a 4 mm blade given by I4. IS-B.)
O7501;
G99 G00 X70 Z5 M3 S500 T0101;
G75.1 X60 Z0 P2000 Q3000 H-16 D-12 B60;
G75.1 R0.3 V6 I4 J1 A1 B1.5 D1 E2 P1001 F0.1;
G00 X100 Z50;
M30;
