(G75.1 with a sloped mouth, L10: a groove cut into a cone whose diameter grows toward -Z at 10 deg)
(blank assets/blanks/cone-10deg.toml: P1 Z0 X40, floor X30 from Z0 to Z-8, both flanks square;)
(the far mouth corner P4 lies on the cone at Z-8 X42.8212. 3 mm blade by I3. IS-B.)
O7503;
G99 G00 X50 Z5 M3 S500 T0101;
G75.1 X40 Z0 P2000 Q2000 H-10 D-8 L10;
G75.1 R0.3 I3 F0.1;
G00 X80 Z50;
M30;
