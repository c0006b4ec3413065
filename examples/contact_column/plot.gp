# Platen stress of the column split by a contact interface (run from the results folder).
set datafile separator ","
set datafile columnheaders
set terminal pngcairo size 900,600 noenhanced
set grid
set key right bottom
ref = system("dirname " . ARG0) . "/../confined_column/reference.csv"
set output "contact_column_stress.png"
set title "Column split by a non-matching contact interface vs whole-model reference"
set xlabel "time [s]"
set xrange [0:200]
set ylabel "stress [MPa]"
plot "history.csv" using 1:(column("upper.zmax.Rz [N]")) with lines lw 2 title "platen stress (contact model)", \
     "history.csv" every ::1 using 1:(-column("contact1.Fz [N]")) with lines dt 2 lw 2 title "contact pressure (interface force on the upper body, sign flipped)", \
     ref using 1:2 with points pt 7 ps 1.3 title "whole-model reference (paper §4.1)"
