# Renders Figs. 3-6 of Panek & Kalker (1980) from panek_kalker's CSV files (the paper's scene:
# f = 9, nu = 0.5, a 5:1 static ellipse, lengths in units of the static long-term a0).
# usage: gnuplot -e "dir='out/panek_kalker'; outdir='docs/figures'" scripts/plot_panek_kalker.gp
# Points where the line solver did not converge (converged = 0 in the sweep) are drawn as open
# circles on top of the curves, and least-squares minima where the line equations have no root
# (converged = 1, root = 0, column 11) as small open squares.
if (!exists("dir")) dir = 'out/panek_kalker'
if (!exists("outdir")) outdir = 'docs/figures'
set datafile separator ','
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
  set terminal pngcairo size 900,600 font ',11'
} else {
  set terminal png size 900,600
}
set key top right
set grid

f = 9.0
glassy_width = (1 + f)**(-1.0/3)                       # a(0)/a0 and l/l0 as V tau -> infinity
glassy_depth = 0.5 * log(20.0) * (1 + f)**(-2.0/3)     # d/(C1 a0^2) = (1+f)^(-2/3) d0/(C1 a0^2)
sweep = dir.'/panek_kalker_sweep.csv'
speeds = "0.01 0.1 0.3 1 3 10 100"

set output outdir.'/panek_kalker_fig3.png'
set logscale x
set format x '10^{%L}'
set xrange [1e-3:1e3]
set yrange [0:1.05]
set xlabel 'V tau / a_0'
set title 'Fig. 3: contact width and offset at y = 0, contact length (f = 9, 5:1 static ellipse)'
set key top right
plot sweep every ::1 using 1:2 with lines lw 2 lc 1 title 'a(0)/a_0', \
     '' every ::1 using 1:3 with lines lw 2 lc 2 title 'b(0)/a_0', \
     '' every ::1 using 1:4 with lines lw 2 lc 3 title 'l/l_0', \
     glassy_width with lines dt 2 lw 2 lc rgb 'black' title sprintf('glassy limit (1+f)^{-1/3} = %.4f', glassy_width), \
     '' every ::1 using ($7 == 0 ? $1 : 1/0):2 with points pt 6 ps 1.2 lc rgb 'red' title 'not converged', \
     '' every ::1 using ($7 == 0 ? $1 : 1/0):3 with points pt 6 ps 1.2 lc rgb 'red' notitle, \
     '' every ::1 using ($7 == 0 ? $1 : 1/0):4 with points pt 6 ps 1.2 lc rgb 'red' notitle, \
     '' every ::1 using ($7 == 1 && $11 == 0 ? $1 : 1/0):2 with points pt 4 ps 0.7 lc rgb '#d95f02' title 'least-squares minimum (no root)', \
     '' every ::1 using ($7 == 1 && $11 == 0 ? $1 : 1/0):3 with points pt 4 ps 0.7 lc rgb '#d95f02' notitle, \
     '' every ::1 using ($7 == 1 && $11 == 0 ? $1 : 1/0):4 with points pt 4 ps 0.7 lc rgb '#d95f02' notitle

set output outdir.'/panek_kalker_fig4.png'
set yrange [0:2.1]
set title 'Fig. 4: rolling friction and penetration (f = 9, 5:1 static ellipse)'
set key top right
plot sweep every ::1 using 1:6 with lines lw 2 lc 1 title 'chi (rolling friction)', \
     '' every ::1 using 1:5 with lines lw 2 lc 2 title 'd/(C_1 a_0^2)', \
     glassy_depth with lines dt 2 lw 2 lc rgb 'black' title sprintf('glassy limit of d/(C_1 a_0^2) = %.4f', glassy_depth), \
     '' every ::1 using ($7 == 0 ? $1 : 1/0):6 with points pt 6 ps 1.2 lc rgb 'red' title 'not converged', \
     '' every ::1 using ($7 == 0 ? $1 : 1/0):5 with points pt 6 ps 1.2 lc rgb 'red' notitle, \
     '' every ::1 using ($7 == 1 && $11 == 0 ? $1 : 1/0):6 with points pt 4 ps 0.7 lc rgb '#d95f02' title 'least-squares minimum (no root)', \
     '' every ::1 using ($7 == 1 && $11 == 0 ? $1 : 1/0):5 with points pt 4 ps 0.7 lc rgb '#d95f02' notitle

set output outdir.'/panek_kalker_fig5.png'
unset logscale x
set format x '%g'
set xrange [*:*]
set yrange [*:*]
set xlabel 'y / a_0 (along the roller axis)'
set ylabel 'x / a_0 (rolling direction, up)'
set title 'Fig. 5: contact zones x = b(y) +- a(y) for several V tau / a_0 (axes not to scale)'
set key outside right
plot for [i=1:words(speeds)] dir.'/panek_kalker_zones.csv' every ::1 \
       using ($1 == word(speeds, i) + 0 ? $2 : 1/0):3 with lines lw 2 lc i title 'V tau/a_0 = '.word(speeds, i), \
     for [i=1:words(speeds)] '' every ::1 using ($1 == word(speeds, i) + 0 ? $2 : 1/0):4 with lines lw 2 lc i notitle

set output outdir.'/panek_kalker_fig6.png'
set xrange [-1:1]
set yrange [0:1.05]
set xlabel 'xi = (x - b(0)) / a(0)   (trailing edge -1, leading edge +1)'
set ylabel 'p(x, 0) / p_{max}'
set title 'Fig. 6: pressure along y = 0, rescaled to the contact width and the peak pressure'
set key outside right
plot for [i=1:words(speeds)] dir.'/panek_kalker_pressure.csv' every ::1 \
       using ($1 == word(speeds, i) + 0 ? $2 : 1/0):3 with lines lw 2 lc i title 'V tau/a_0 = '.word(speeds, i)
