# Tip displacement and clamp reaction of the cantilever example (run from the results folder).
set datafile separator ","
set datafile columnheaders
set terminal pngcairo size 900,600 noenhanced
set key autotitle columnhead
set output "cantilever_tip.png"
set title "Neo-Hookean cantilever under follower pressure"
set xlabel "load factor (time) [-]"
set ylabel "tip displacement [mm]"
set grid
plot "history.csv" using 1:(column("tip.ux [mm]")) with linespoints title "u_x", \
     "" using 1:(column("tip.uz [mm]")) with linespoints title "u_z"
set output "cantilever_reaction.png"
set ylabel "clamp reaction [N]"
plot "history.csv" using 1:(column("beam.xmin.Rx [N]")) with linespoints title "R_x", \
     "" using 1:(column("beam.xmin.Rz [N]")) with linespoints title "R_z"
