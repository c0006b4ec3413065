# Cook's membrane under a sudden shear load (run in the output folder: gnuplot plot.gp).
set datafile separator ","
set datafile columnheaders
set terminal pngcairo size 900,600 noenhanced
set grid
set output "cook_tip.png"
set title "Cook's membrane, nearly incompressible (kappa = 1000 mu): tip deflection"
set xlabel "time [ms]"
set ylabel "mean u_y of the loaded edge [mm]"
set key top right
plot "history.csv" using (column("time [s]")*1e3):(column("tip_uy [mm]")) with lines lw 2 title "Q1-P0 multiplier (explicit A2 scheme)", \
     "history_q1.csv" using (column("time [s]")*1e3):(column("tip_uy [mm]")) with lines lw 2 title "pure-displacement Q1 (locks)"
set output "cook_energy.png"
set title "Q1-P0 run: energy bookkeeping and volume change"
set ylabel "energy [mJ]"
set y2label "max |Jbar - 1|"
set y2tics
set key right center
plot "history.csv" using (column("time [s]")*1e3):(column("kinetic [mJ]")) with lines lw 2 title "kinetic", \
     "" using (column("time [s]")*1e3):(column("strain [mJ]")) with lines lw 2 title "strain", \
     "" using (column("time [s]")*1e3):(column("external_work [mJ]")) with lines lw 2 title "external work", \
     "" using (column("time [s]")*1e3):(column("total_energy [mJ]")) with lines lw 2 title "total", \
     "" using (column("time [s]")*1e3):(column("max|Jbar-1|")) axes x1y2 with lines lw 1 dt 2 title "max |Jbar - 1| (right axis)"
