(ID boring toward the chuck with G41 and tip 2 on a tube Φ60 × 40 with a Φ30 bore:)
(one roughing pass, then the finish bore Φ40 with a 2 mm × 45° chamfer to Φ44 at the face)
O0041;
G99 M03 S900;
T0202;
G00 X28. Z5.;
G00 X39.5 Z2.;
G01 Z-42. F0.2;
G00 X28.;
G00 Z5.;
G41 G01 X46. Z1. F0.1;
G01 X40. Z-2.;
G01 Z-42.;
G40 G00 X28.;
G00 Z5.;
M30;
