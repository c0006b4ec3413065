# Tip deflection and energy bookkeeping of the explicit cantilever (run from the results folder:
# gnuplot -c plot.gp).
set datafile separator ","
set datafile columnheaders
set terminal pngcairo size 900,600 noenhanced
set grid
set output "explicit_cantilever_tip.png"
set title "Suddenly loaded nearly incompressible cantilever: tip displacement"
set xlabel "time [ms]"
set ylabel "tip displacement [mm]"
set key bottom right
plot "history.csv" using (column("time [s]")*1e3):(column("tip.uz [mm]")) with lines lw 2 title "u_z (transverse)", \
     "" using (column("time [s]")*1e3):(column("tip.ux [mm]")) with lines lw 2 title "u_x (axial)"
set output "explicit_cantilever_energy.png"
set title "Energy bookkeeping (undamped: total = kinetic + strain - external work stays at 0)"
set ylabel "energy [mJ]"
set y2label "max |Jbar - 1|"
set y2tics
set key below
plot "history.csv" using (column("time [s]")*1e3):(column("kinetic [mJ]")) with lines lw 2 title "kinetic", \
     "" using (column("time [s]")*1e3):(column("strain [mJ]")) with lines lw 2 title "strain", \
     "" using (column("time [s]")*1e3):(column("external_work [mJ]")) with lines lw 2 title "external work", \
     "" using (column("time [s]")*1e3):(column("total_energy [mJ]")) with lines lw 2 title "total", \
     "" using (column("time [s]")*1e3):(column("max|Jbar-1|")) axes x1y2 with lines lw 1 dt 2 title "max |Jbar - 1| (right axis)"
