O0712 (G71 type II on a bar 60 x 80, face Z0: a pocket from Φ30 down to Φ20 and up to Φ40; latsim contour-cycle acceptance)
G99 M03 S800 T0101
G00 X62 Z2
G71 U1.5 R0.5
G71 P10 Q20 U0.4 W0.1 F0.25
N10 G00 X30 Z1
G01 Z-10 F0.1
X20 Z-20
Z-30
X40 Z-40
Z-50
N20 X62
G70 P10 Q20
M30
