# Radial oscillation of the thick sphere (run in the output folder: gnuplot plot.gp).
set datafile separator ","
set datafile columnheaders
set terminal pngcairo size 900,600 noenhanced
set grid
set output "sphere_radius.png"
set title "Thick sphere A = 10, B = 20 mm under a step pressure 0.3 mu: inner radius"
set xlabel "time [ms]"
set ylabel "inner radius [mm]"
set key right bottom
plot "reference.csv" using ($1*1e3):2 with lines lw 3 lc rgb "#999999" title "exact (radial ODE, RK4)", \
     "history.csv" using (column("time [s]")*1e3):(column("inner_radius [mm]")) with lines lw 1.5 lc rgb "#c00000" title "trifem explicit (octant)"
set output "sphere_energy.png"
set title "Energy bookkeeping (undamped: total should stay at 0)"
set ylabel "energy [mJ]"
set key top left
plot "history.csv" using (column("time [s]")*1e3):(column("kinetic [mJ]")) with lines lw 2 title "kinetic", \
     "" using (column("time [s]")*1e3):(column("strain [mJ]")) with lines lw 2 title "strain", \
     "" using (column("time [s]")*1e3):(column("external_work [mJ]")) with lines lw 2 title "external work", \
     "" using (column("time [s]")*1e3):(column("total_energy [mJ]")) with lines lw 2 title "total = K + W - W_ext"
