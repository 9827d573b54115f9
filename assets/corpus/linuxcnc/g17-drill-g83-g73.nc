(LinuxCNC lathe: a Phi16 hole drilled on the axis in G17, G83 then G73)
G18 G21 G7 G90 G95
T8 M6 G43 (16 mm drill)
G97 S600 M3
G0 X0 Z5
G17 (the XY plane: its drilling cycles drill along Z, the lathe's axis)
G99 G83 Z-20 R2 Q6 F0.12
G80
G98 G73 Z-30 R-18 Q4 D0.5
G80
G18
G0 X60
M5
M2
