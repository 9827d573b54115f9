%
(MSG, a pawn-like part: G71.1 roughs without the neck, G71.2 the neck, G70 finishes)
G18 G21 G7 G90 G40 G95
T7 M6 G43                     ; D55 r0.8 roughing
G96 D2500 S180 M3
F0.25
o100 sub                      ; the profile, read by the cycles only
  G1 X0 Z0
  G3 X12 Z-6 R6               ; the ball
  G1 X8 Z-16                  ; down into the neck
  Z-20
  X20 Z-26
  Z-30
  X28 Z-34
  Z-40
  X34
o100 endsub
G0 X34 Z2
G71.1 Q100 X34 Z2 D0.4 I1.5 R0.5
G71.2 Q100 X34 Z2 D0.4 I1.5 R0.5
G0 X60 Z50
T2 M6 G43                     ; D55 r0.4 finishing
G96 D3000 S220 M3
F0.1
G0 X34 Z2
G42.1 D0.8 L2                 ; nose r0.4, orientation 2
G70 Q100 X34 Z2
G40 G0 X60 Z50               ; the cancel move
M5
M2
%
