# Platen stress and outflow of the paper's 4.1 column (run from the results folder).
set datafile separator ","
set datafile columnheaders
set terminal pngcairo size 900,600 noenhanced
set grid
set key right bottom
ref = system("dirname " . ARG0) . "/reference.csv"
set output "confined_column_stress.png"
set title "Confined triphasic column: total axial stress on the platen (area 1 mm^2)"
set xlabel "time [s]"
set ylabel "total stress [MPa]"
plot "history.csv" using 1:(column("column.zmax.Rz [N]")) with lines lw 2 title "trifem (reaction / area)", \
     ref using 1:2 with points pt 7 ps 1.3 title "reference solution (paper §4.1)"
set output "confined_column_outflow.png"
set title "Water squeezed out through the porous platen"
set ylabel "water outflow [mm^3/s]"
set key right top
plot "history.csv" using 1:(column("water_outflow [mm^3/s]")) with lines lw 2 title "outflow"
