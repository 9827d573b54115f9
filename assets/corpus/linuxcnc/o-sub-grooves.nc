%
(MSG, three grooves by an o-word subroutine called from a while loop)
G18 G21 G7 G90 G40 G95 ; diameter mode, mm/rev
T5 M6 G43                 ; 3 mm blade, referenced at its left corner
G97 S600 M3
o<groove> sub
  ; #1 = Z of the groove's left wall, #2 = bottom diameter
  G0 X42 Z#1
  G1 X#2 F0.05
  G0 X42
o<groove> endsub
#<z> = -10
o100 while [#<z> GE -26]
  o<groove> call [#<z>] [34]
  #<z> = [#<z> - 8]
o100 endwhile
G0 X60 Z50
M5
M2
%
