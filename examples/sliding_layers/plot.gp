# Interface distributions along the condyle during the first half of the second cycle
# (cf. the paper's Figs. 7-10) and the load/sliding histories. Run from the results folder:
#   gnuplot -c plot.gp
set datafile separator ","
set datafile columnheaders
set terminal pngcairo size 900,600 noenhanced
set grid

# the surface files of the wanted times (0 -> +A -> 0 of the second cycle)
wanted = "0.402 0.452 0.502 0.552 0.602"
selected = ""
labels = ""
files = system("ls contact1_surface_*.csv")
do for [f in files] {
  stats f using 1 nooutput
  do for [w in wanted] {
    if (abs(STATS_min - w) < 1e-9) {
      selected = selected . " " . f
      labels = labels . " " . sprintf("t=%.3f_s", STATS_min)
    }
  }
}
n = words(selected)
set xlabel "x of the condyle surface (current) [mm]"
set key outside right

set output "sliding_contact_pressure.png"
set title "Contact pressure -t along the interface (second cycle, 0 -> +A -> 0)"
set ylabel "-t [MPa]"
plot for [i=1:n] word(selected, i) using "x [mm]":(-column("contact_traction [MPa]")) \
     with linespoints lw 2 title word(labels, i)

set output "sliding_fluid_potential.png"
set title "Water chemical potential on the interface"
set ylabel "mu_w (bath = 0) [MPa]"
plot for [i=1:n] word(selected, i) using "x [mm]":"fluid_chemical_potential [MPa]" \
     with linespoints lw 2 title word(labels, i)

set output "sliding_ion_potentials.png"
set title "Ion electrochemical potentials on the interface (cation solid, anion dashed)"
set ylabel "mu (bath = 0) [mJ/mmol]"
plot for [i=1:n] word(selected, i) using "x [mm]":"cation_electrochemical_potential [mJ/mmol]" \
     with lines lw 2 lc i title word(labels, i), \
     for [i=1:n] word(selected, i) using "x [mm]":"anion_electrochemical_potential [mJ/mmol]" \
     with lines lw 2 dt 2 lc i notitle

set output "sliding_normal_flux.png"
set title "Normal water flux through the interface (out of the condyle > 0)"
set ylabel "w.n [mm/s]"
plot for [i=1:n] word(selected, i) using "x [mm]":"normal_fluid_flux [mm/s]" \
     with linespoints lw 2 title word(labels, i)

set output "sliding_history.png"
set title "Condyle: sliding, sinking and forces"
set xlabel "time [s]"
set key inside right top
set ylabel "displacement [mm]"
set y2label "force [N]"
set y2tics
plot "history.csv" using 1:"condyle.ux [mm]" with lines lw 2 title "condyle u_x (prescribed)", \
     "history.csv" using 1:"condyle.uy [mm]" with lines lw 2 title "condyle u_y (sinking)", \
     "history.csv" using 1:(-column("condyle.Fy [N]")) axes x1y2 with lines lw 2 title "applied load -F_y", \
     "history.csv" using 1:"contact1.Fy [N]" axes x1y2 with lines dt 2 lw 2 title "contact force on the condyle F_y", \
     "history.csv" using 1:(column("condyle.Fx [N]")*100) axes x1y2 with lines lw 2 title "horizontal force F_x x 100"
