# Error against run time of the line solver and the 3-D BEM on the paper's scene (f = 9, 5:1,
# lengths in units of the line theory's static a0), from benchmarks/error_vs_time.cpp's CSV.
# One row of panels per speed V tau/a0, one column per quantity (a(0), b(0), l, d, chi);
# log-log relative error against the wall seconds of a cold solve (one core).
#   blue  line solver (terms 2 ... 32): solid = against its own reference (largest converged
#         terms), dashed = against the BEM reference; open symbols = not converged
#         (converged == false: uncertified values, never drawn as part of the solid curves);
#   red   BEM (N = 4 ... 64 elements per semi-axis): solid = against its finest grid,
#         dashed = against the line solver's reference.
# Dotted verticals: the run time of each method's reference (its self error is 0, not drawn).
# The dashed curves level off at the line theory's modelling error (plus the references' own
# discretisation errors); the solid ones measure the discretisation error only.
# usage: gnuplot -e "dir='docs/figures'; outdir='docs/figures'" scripts/plot_error_vs_time.gp
if (!exists("dir")) dir = 'docs/figures'
if (!exists("outdir")) outdir = 'docs/figures'
if (!exists("speeds")) speeds = '0.1 1 10'
set datafile separator ','
set datafile columnheaders
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
  set terminal pngcairo size 2200,1450 font ',11'
} else {
  set terminal png size 2200,1450
}
data = dir.'/error_vs_time.csv'
set output outdir.'/error_vs_time.png'

# CSV columns: 1 method, 2 vtau, 3 n, 4 converged, 5 seconds, 6 cpu_seconds, 7 repetitions,
# 8-12 a0 b0 l d chi, 13-17 self_<q>, 18-22 cross_<q>, 23 is_reference.
titles = "a(0) b(0) l d chi"
rows = words(speeds)
pos(x) = x > 0 ? x : NaN
is(m, v) = strcol(1) eq m && abs(column(2) / v - 1) < 1e-9
sel(m, v, conv) = is(m, v) && column(4) == conv ? column(5) : NaN

# Reference discretisation of each method and speed (panel titles) and its run time (a dotted
# vertical line in the method's colour: the self errors are measured against that point).
array lref[rows]
array bref[rows]
array lsec[rows]
array bsec[rows]
do for [r = 1:rows] {
  v = real(word(speeds, r))
  stats data u (is('line', v) && column(23) == 1 ? column(3) : NaN) nooutput
  lref[r] = STATS_records > 0 ? sprintf('%d', STATS_max) : 'none'
  stats data u (is('line', v) && column(23) == 1 ? column(5) : NaN) nooutput
  lsec[r] = STATS_records > 0 ? STATS_max : NaN
  stats data u (is('bem', v) && column(23) == 1 ? column(3) : NaN) nooutput
  bref[r] = STATS_records > 0 ? sprintf('%d', STATS_max) : 'none'
  stats data u (is('bem', v) && column(23) == 1 ? column(5) : NaN) nooutput
  bsec[r] = STATS_records > 0 ? STATS_max : NaN
}

set multiplot layout rows, 5 title "Relative error against run time, paper's scene (f = 9, 5:1): line solver (blue) and 3-D BEM (red); solid = self-convergence, dashed = against the other method; open = not converged" font ',13'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xrange [2e-3:30]
set yrange [1e-10:1]
set ytics 1e-10, 100, 1
set mytics 10
set grid xtics ytics
# The 1%, 0.1%, 0.01% levels of docs/performance.md's table.
do for [k = 2:4] {
  set arrow k from graph 0, first 10.0**(-k) to graph 1, first 10.0**(-k) nohead dt 3 lc rgb '#777777'
}
set key bottom left font ',9' samplen 2 spacing 0.9 opaque
do for [r = 1:rows] {
  v = real(word(speeds, r))
  unset arrow 5
  unset arrow 6
  if (lsec[r] == lsec[r]) { set arrow 5 from first lsec[r], graph 0 to first lsec[r], graph 1 nohead dt 3 lw 1.5 lc rgb '#1f5fbf' }
  if (bsec[r] == bsec[r]) { set arrow 6 from first bsec[r], graph 0 to first bsec[r], graph 1 nohead dt 3 lw 1.5 lc rgb '#d62728' }
  do for [q = 1:5] {
    set title sprintf('%s, V tau/a_0 = %g  (refs: line terms %s, BEM N = %s)', word(titles, q), v, lref[r], bref[r]) font ',11'
    if (q == 1) { set ylabel 'relative error' } else { unset ylabel }
    if (r == rows) { set xlabel 'wall seconds (cold solve, one core)' } else { unset xlabel }
    if (r == 1 && q == 1) { set key } else { unset key }
    plot data u (sel('line', v, 1)):(pos(column(12 + q))) w lp lw 2 pt 7 ps 0.9 lc rgb '#1f5fbf' t 'line, vs own reference', \
         data u (sel('line', v, 1)):(pos(column(17 + q))) w lp lw 1.5 dt 2 pt 9 ps 0.8 lc rgb '#1f5fbf' t 'line, vs BEM reference', \
         data u (sel('line', v, 0)):(pos(column(12 + q))) w p pt 6 ps 1.4 lw 1.5 lc rgb '#1f5fbf' t 'line, NOT converged (vs own ref.)', \
         data u (sel('line', v, 0)):(pos(column(17 + q))) w p pt 8 ps 1.2 lw 1.5 lc rgb '#1f5fbf' t 'line, NOT converged (vs BEM ref.)', \
         data u (sel('bem', v, 1)):(pos(column(12 + q))) w lp lw 2 pt 5 ps 0.8 lc rgb '#d62728' t 'BEM, vs own reference', \
         data u (sel('bem', v, 1)):(pos(column(17 + q))) w lp lw 1.5 dt 2 pt 11 ps 0.8 lc rgb '#d62728' t 'BEM, vs line reference', \
         data u (sel('bem', v, 0)):(pos(column(12 + q))) w p pt 4 ps 1.4 lw 1.5 lc rgb '#d62728' t 'BEM, NOT converged'
  }
}
unset multiplot
