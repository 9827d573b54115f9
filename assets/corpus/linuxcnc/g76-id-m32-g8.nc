%
(MSG, M32 x 2 inside thread by one G76 block, LinuxCNC style, radius mode)
G18 G21 G8 G90 G95
T13 M6 G43
G97 S500 M4
G0 X14.5 Z4 ; the drive line (radius 14.5), 0.5 inside the bore
G76 P2 Z-24 I0.5 J0.3 K1.1 R2 Q29.5 H1
G0 Z5 ; out of the bore first: the cycle ends inside it
X40
M5
M2
%
