%
(MSG, facing by repeat with a finishing pass chosen by if, named parameters)
G18 G21 G7 G90 G40 G95
T1 M6 G43
G96 D2500 S200 M3
#<_stock> = 1.5               ; to face off, mm
#<step> = 0.5
#<z> = 0
o10 repeat [#<_stock> / #<step>]
  #<z> = [#<z> - #<step>]
  o20 if [#<z> LE [0 - #<_stock>]]
    F0.08                     ; the last pass: finishing feed
  o20 else
    F0.2
  o20 endif
  G0 X44 Z[#<z> + 1.5]
  G0 Z#<z>
  G1 X-1.6
  G0 Z[#<z> + 1]
o10 endrepeat
G0 X60 Z50
M5
M2
%
