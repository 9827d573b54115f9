%
(MSG, a stepped shaft in radius mode, LinuxCNC style)
G18 G21 G8 G90 G40 G49 G95 ; safe start: diameter mode, mm/rev
T1 M6 G43                   ; tool 1 and its length offset
G96 D2500 S180 M3           ; 180 m/min, clamped at 2500 rpm
G0 X21 Z2
X18
G1 Z-30 F0.2
X21
G0 Z2
X16
G1 Z-20
X18
G0 Z2
G97 S800
G0 X50 Z50
M5
M2
%
