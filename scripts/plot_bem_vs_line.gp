# Line-contact theory against the exact 3-D boundary-element solver on the paper's scene
# (f = 9, nu = 0.5, 5:1, lengths in units of the line theory's static a0), from bem_vs_line's CSV
# files (benchmarks/bem_vs_line.cpp). Five panels: a(0), b(0), l, d, chi against V tau / a0;
# the line solver as a curve, the BEM at each grid as points, the Richardson extrapolation of the
# two finest grids as a dashed curve; and the BEM's grid convergence at V tau / a0 = 1.
# usage: gnuplot -e "dir='docs/figures'; outdir='docs/figures'" scripts/plot_bem_vs_line.gp
if (!exists("dir")) dir = 'docs/figures'
if (!exists("outdir")) outdir = 'docs/figures'
set datafile separator ','
set datafile columnheaders
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
  set terminal pngcairo size 1200,1000 font ',10'
} else {
  set terminal png size 1200,1000
}
data = dir.'/bem_vs_line.csv'
conv = dir.'/bem_convergence.csv'
f = 9.0

set output outdir.'/bem_vs_line.png'
set multiplot layout 3,2 title 'Line-contact theory (curve) against the 3-D BEM (points: N = 8, 16, 32 per semi-axis; dashed: Richardson)'
set logscale x
set format x '10^{%L}'
set xrange [0.005:200]
set xlabel 'V tau / a_0'
set grid
set key top right font ',9'
# Column layout: 1 vtau, 2-6 line a0 b0 l d chi, 7 line_converged, then per grid 7 columns
# (a0 b0 l d chi converged seconds) for N = 8, 16, 32 starting at 8, 15, 22, then Richardson 29-33.
titles = "a(0)/a_0 b(0)/a_0 l/a_0 d/(C_1a_0^2) chi"
do for [q = 1:5] {
  set title word(titles, q)
  set ylabel word(titles, q)
  if (q == 1) { set arrow 1 from 0.005, (1+f)**(-1.0/3) to 200, (1+f)**(-1.0/3) nohead dt 3 lc rgb 'gray' } else { unset arrow 1 }
  plot data u 1:(column(1 + q)) w l lw 2 lc rgb 'black' t 'line theory', \
       data u 1:(column(7 + q)) w p pt 6 ps 1.0 lc rgb '#1f77b4' t 'BEM N = 8', \
       data u 1:(column(14 + q)) w p pt 4 ps 1.0 lc rgb '#ff7f0e' t 'BEM N = 16', \
       data u 1:(column(21 + q)) w lp pt 7 ps 0.8 lc rgb '#d62728' t 'BEM N = 32', \
       data u 1:(column(28 + q)) w l dt 2 lw 1.5 lc rgb '#d62728' t 'Richardson'
}
unset logscale x
set format x '%g'
set xrange [*:*]
set logscale x
set xlabel '1/N'
set title 'BEM grid convergence at V tau / a_0 = 1 (relative to N = 64)'
set ylabel 'relative difference'
unset logscale y
set format y '%.0e'
set xrange [0.01:0.15]
stats conv every ::6::6 u 5 nooutput
d64 = STATS_max
stats conv every ::6::6 u 6 nooutput
chi64 = STATS_max
stats conv every ::6::6 u 2 nooutput
a64 = STATS_max
stats conv every ::6::6 u 4 nooutput
l64 = STATS_max
set yrange [-0.06:0.06]
set format y '%.2f'
set key bottom right
plot conv u (1/$1):($5/d64 - 1) w lp pt 7 t 'd', \
     conv u (1/$1):($6/chi64 - 1) w lp pt 5 t 'chi', \
     conv u (1/$1):($2/a64 - 1) w lp pt 9 t 'a(0)', \
     conv u (1/$1):($4/l64 - 1) w lp pt 11 t 'l'
unset multiplot
