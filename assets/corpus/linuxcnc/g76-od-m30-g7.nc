%
(MSG, M30 x 1.5 outside thread by one G76 block, LinuxCNC style, diameter mode)
G18 G21 G7 G90 G95
T4 M6 G43
G97 S600 M3
G0 X31 Z3 ; the drive line, 0.5 above the thread peak (radius)
; I J K are diameters under G7: peak 0.5 below the drive line, first cut 0.25, full depth 0.9
G76 P1.5 Z-20 I-1 J0.5 K1.8 R2 Q29.5 H1
G0 X50 Z20
M5
M2
%
