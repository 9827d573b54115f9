o0006; (seed 003 O0006 without its G70 line: the G73 roughing alone, for the allowance test)
g99 g00 x200 z10 m03 s500; (指定每轉進給,定位起點,啟動主軸)
g73 u1.0 w1.0 r3 ; (x軸退刀2mm,z軸退刀1mm)
g73 p14 q19 u0.5 w0.3 f0.3 ; (粗車,x軸留0.5mm,z軸留0.3mm精車餘量)
n14 g00 x80 z0 ;
g01 w-20 f0.15 s600 ;
x120 w-10 ;
w-20 ; 精加工形狀程式段
g02 x160 w-20 r20 ;
n19 g01 x180 w-10 ;
m30;
