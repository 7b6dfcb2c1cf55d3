set terminal pngcairo size 1200,500 font ',11'
set output 'figures/approximations.png'
set multiplot layout 1,2
set logscale x; set yrange [0:1.05]; set xlabel 'eps = v/(R omega)'; set ylabel 'F, T'; set key right center
plot 'approximations.csv' u 1:2 w l lw 3 lc 'black' t 'F exact', '' u 1:3 w l lw 3 dt 2 lc 'black' t 'T exact', '' u 1:4 w l lc 'red' t 'F caps', '' u 1:5 w l dt 2 lc 'red' t 'T caps', '' u 1:6 w l lc 'blue' t 'F elliptic', '' u 1:7 w l dt 2 lc 'blue' t 'T elliptic', '' u 1:8 w l lc 'dark-green' t 'F Pade', '' u 1:9 w l dt 2 lc 'dark-green' t 'T Pade'
unset logscale x; set yrange [0:0.75]; set xrange [0:1.05]; set xlabel 'F'; set ylabel 'T'; set key left bottom
plot 'approximations.csv' u 2:3 w l lw 3 lc 'black' t 'exact limit curve', '' u 6:7 w l lc 'blue' t 'elliptic', '' u 8:9 w l lc 'dark-green' t 'Pade', '-' w p pt 7 ps 1.5 lc 'red' t 'caps (a corner)'
1 0.6666667
e
unset multiplot
