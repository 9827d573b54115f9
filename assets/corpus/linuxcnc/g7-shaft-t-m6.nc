%
(MSG, a stepped shaft in diameter mode, LinuxCNC style)
G18 G21 G7 G90 G40 G49 G95 ; safe start: diameter mode, mm/rev
T1 M6 G43                   ; tool 1 and its length offset
G96 D2500 S180 M3           ; 180 m/min, clamped at 2500 rpm
G0 X42 Z2
X36
G1 Z-30 F0.2
X42
G0 Z2
X32
G1 Z-20
X36
G0 Z2
G97 S800
G0 X100 Z50
M5
M2
%
