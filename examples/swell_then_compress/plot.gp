# Swelling then confined compression: step 1 (swelling, log time) and step 2 (compression,
# time since its start) from history.csv.
set datafile separator ","
set datafile columnheaders
set terminal pngcairo size 900,900 noenhanced
set grid
set output "swell_then_compress.png"
set multiplot layout 3,1 title "Free swelling (step 1), then confined compression (step 2)"
t1 = 20000.0
set logscale x
set xrange [1:t1]
set xlabel "time [s] (step 1)"
set ylabel "u_z at the top [mm]"
plot "history.csv" using 1:(column("top.uz [mm]")) with lines lw 2 title "swelling (closed form 0.225066 mm)"
unset logscale x
set xrange [0:2000]
set xlabel "time since the start of step 2 [s]"
set ylabel "top reaction R_z [N]"
plot "history.csv" using ($1 >= t1 ? $1 - t1 : 1/0):(column("layer.zmax.Rz [N]")) with linespoints pt 7 ps 0.5 lw 2 title "compression 0.1 mm in 200 s, hold"
set ylabel "fluid pressure at the centre [MPa]"
plot "history.csv" using ($1 >= t1 ? $1 - t1 : 1/0):(column("centre.fluid_pressure [MPa]")) with linespoints pt 7 ps 0.5 lw 2 notitle
unset multiplot
