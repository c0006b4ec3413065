# Tip displacement and clamp reaction of the cantilever example (run from the results folder).
set datafile separator ","
set terminal pngcairo size 900,600 noenhanced
set key autotitle columnhead
set output "cantilever_tip.png"
set title "Neo-Hookean cantilever under follower pressure"
set xlabel "load factor (time) [-]"
set ylabel "tip displacement [mm]"
set grid
plot "history.csv" using 1:8 with linespoints title "u_x", \
     "" using 1:10 with linespoints title "u_z"
set output "cantilever_reaction.png"
set ylabel "clamp reaction [N]"
plot "history.csv" using 1:5 with linespoints title "R_x", \
     "" using 1:7 with linespoints title "R_z"
