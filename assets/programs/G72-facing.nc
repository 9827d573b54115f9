O0721 (G72 facing on a bar 60 x 80, face Z0: face Z-12 down to Φ40, 45° cone to Φ30, chamfer; latsim contour-cycle acceptance)
G99 M03 S800 T0101
G00 X64 Z2
G72 W2 R0.5
G72 P10 Q20 U0.4 W0.2 F0.2
N10 G00 Z-12
G01 X40 F0.1
X30 Z-7
Z-2
X26 Z0
N20 X0
G70 P10 Q20
M30
