# Renders the plane (Hunter) figures from plane_rolling's CSV files.
# usage: gnuplot -e "dir='out/plane'; outdir='docs/figures'" scripts/plot_plane.gp
if (!exists("dir")) dir = 'out/plane'
if (!exists("outdir")) outdir = 'docs/figures'
set datafile separator ','
set terminal pngcairo size 900,600 font ',11'
set key top right
set grid

set output outdir.'/plane_contact_vs_speed.png'
set logscale x
set format x '10^{%L}'
set xlabel 'V tau / a_0'
set title 'Plane problem: contact half width, offset and rolling friction (a_0 = long-term Hertz width)'
plot dir.'/plane_sweep.csv' every ::1 using ($2==9 ? $1 : 1/0):3 with lines lw 2 title 'a/a_0, f = 9', \
     '' every ::1 using ($2==9 ? $1 : 1/0):4 with lines lw 2 title 'b/a_0, f = 9', \
     '' every ::1 using ($2==9 ? $1 : 1/0):5 with lines lw 2 title 'chi/(C_1 a_0), f = 9', \
     '' every ::1 using ($2==1 ? $1 : 1/0):3 with lines dt 2 lw 2 title 'a/a_0, f = 1', \
     '' every ::1 using ($2==1 ? $1 : 1/0):4 with lines dt 2 lw 2 title 'b/a_0, f = 1', \
     '' every ::1 using ($2==1 ? $1 : 1/0):5 with lines dt 2 lw 2 title 'chi/(C_1 a_0), f = 1'

set output outdir.'/plane_pressure.png'
unset logscale x
set format x '%g'
set xlabel 'x / a_0 (roller axis at 0, rolling towards +x)'
set ylabel 'p a_0 / W'
set title 'Plane problem, f = 9: pressure for several V tau / a_0 (leading edge on the right)'
set key top left
plot for [v in "0.01 0.1 1 10 100"] dir.'/plane_pressure.csv' every ::1 using ($1==v+0 ? $2 : 1/0):3 with lines lw 2 title 'V tau/a_0 = '.v
