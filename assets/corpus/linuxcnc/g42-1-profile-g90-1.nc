(MSG, finishing a shoulder with dynamic compensation, LinuxCNC style)
G18 G21 G7 G90 G91.1 G40 G95
T2 M6 G43
G97 S1000 M3
G0 X44 Z2
G42.1 D0.8 L2 ; D55 r0.4 nose, orientation 2 (FANUC tip 3)
G1 X26 Z0 F0.1
Z-10
G90.1 ; absolute arc centre: I is the centre's radius, K its Z
G3 X36 Z-15 I13 K-15
G91.1
G1 Z-25
X44
G40 G0 X50 Z5
G4 P0.5
M5
M2
