# F0(y) of the rolling line solver and the BEM for the crowned rollers of docs/validation.md
# ("Rolling rollers of any profile", "Tilted rollers"), from the CSV files of line_vs_bem_profile:
#   build/release/bin/line_vs_bem_profile 48 12 DIR
#   gnuplot -e "dir='DIR'" benchmarks/line_vs_bem_profile.gp   (writes line_vs_bem_profile.png)
if (!exists("dir")) dir = "."
set terminal pngcairo size 1600,420 font ",10"
set output "line_vs_bem_profile.png"
set datafile separator ","
set key top left
set xlabel "y (units of 1/C1)"
set ylabel "load per length F0/((1 + f) c)"
speeds = "0.1 1 10"
set multiplot layout 1,3
set title "crowned, flat part 10, crown radius 20"
plot for [i=1:3] dir."/flat10_v".word(speeds, i).".csv" every ::1 using 1:2 with points pt 7 ps 0.5 lc i \
       title "BEM, V tau/a0 = ".word(speeds, i), \
     for [i=1:3] dir."/flat10_v".word(speeds, i).".csv" every ::1 using 1:3 with lines lw 1.5 lc i \
       title "line, V tau/a0 = ".word(speeds, i)
set title "logarithmic crown, length 16"
plot for [i=1:3] dir."/log16_v".word(speeds, i).".csv" every ::1 using 1:2 with points pt 7 ps 0.5 lc i \
       title "BEM, V tau/a0 = ".word(speeds, i), \
     for [i=1:3] dir."/log16_v".word(speeds, i).".csv" every ::1 using 1:3 with lines lw 1.5 lc i \
       title "line, V tau/a0 = ".word(speeds, i)
set title "the same crowned roller tilted by 0.003 rad"
plot for [i=1:3] dir."/flat10_tilted_v".word(speeds, i).".csv" every ::1 using 1:2 with points pt 7 \
       ps 0.5 lc i title "BEM, V tau/a0 = ".word(speeds, i), \
     for [i=1:3] dir."/flat10_tilted_v".word(speeds, i).".csv" every ::1 using 1:3 with lines \
       lw 1.5 lc i title "line, V tau/a0 = ".word(speeds, i)
unset multiplot
