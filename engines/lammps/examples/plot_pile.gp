# docs/figures/lammps_pile.png from in.pile's output (docs/lammps.md):
# run in the directory holding pile_yes.* and pile_no.* (coupled, uncoupled):
#   gnuplot -e "out='docs/figures/lammps_pile.png'" engines/lammps/examples/plot_pile.gp
# (a) the distribution of t = |M|/(mu N a) over the sphere-sphere contacts of
#     the settled pile (t = 6, the last step), with the caps: 3 pi/16 (the
#     coupled cap at pure spin) and 2/3 (Marshall's, uncoupled);
# (b) the fraction of the contacts at the friction limit, and (c) the mean
#     |M| per contact, during the pour and settling.
if (!exists("out")) out = 'lammps_pile.png'
set terminal pngcairo size 1500,480 font ",11"
set output out
set multiplot layout 1,3

bw = 0.02
bin(x) = bw * (floor(x / bw) + 0.5)
stats 'pile_yes.contacts' skip 9 using 2 name 'Y' nooutput
stats 'pile_no.contacts' skip 9 using 2 name 'N' nooutput

set title '(a) twisting torque in the settled pile'
set xlabel '|M| / (μ N a)'
set ylabel 'probability density'
set xrange [0:0.7]
set yrange [0:*]
set arrow 1 from 3*pi/16, graph 0 to 3*pi/16, graph 1 nohead dt 2 lc rgb '#1f77b4'
set arrow 2 from 2./3, graph 0 to 2./3, graph 1 nohead dt 2 lc rgb '#d62728'
set label 1 '3π/16' at 3*pi/16, graph 0.55 right offset -0.5,0 tc rgb '#1f77b4'
set label 2 '2/3' at 2./3, graph 0.45 right offset -0.5,0 tc rgb '#d62728'
set key at graph 0.8, graph 0.95 right
plot 'pile_yes.contacts' skip 9 using (bin($2)):(1.0 / (Y_records * bw)) smooth frequency \
       with histeps lw 2 lc rgb '#1f77b4' title sprintf('coupled (mean %.3f)', Y_mean), \
     'pile_no.contacts' skip 9 using (bin($2)):(1.0 / (N_records * bw)) smooth frequency \
       with histeps lw 2 lc rgb '#d62728' title sprintf('uncoupled (mean %.3f)', N_mean)
unset arrow 1
unset arrow 2
unset label 1
unset label 2

set title '(b) contacts at the friction limit'
set xlabel 'time (lj units; Δt = 5·10^{-4})'
set ylabel 'fraction of sphere–sphere contacts'
set xrange [0:6]
set yrange [0:1]
set logscale y
set yrange [0.005:1]
set key top right
plot 'pile_yes.series' using ($1 * 5e-4):($2 > 0 ? $3 : 1/0) with lines lw 2 lc rgb '#1f77b4' title 'coupled', \
     'pile_no.series' using ($1 * 5e-4):($2 > 0 ? $3 : 1/0) with lines lw 2 lc rgb '#d62728' title 'uncoupled'
unset logscale y

set title '(c) mean twisting torque per contact'
set ylabel 'Σ|M| / contacts'
set yrange [0:*]
set key top right
plot 'pile_yes.series' using ($1 * 5e-4):($2 > 0 ? $5 : 1/0) with lines lw 2 lc rgb '#1f77b4' title 'coupled', \
     'pile_no.series' using ($1 * 5e-4):($2 > 0 ? $5 : 1/0) with lines lw 2 lc rgb '#d62728' title 'uncoupled'
unset multiplot
