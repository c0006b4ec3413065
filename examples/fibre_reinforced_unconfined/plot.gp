# Platen stress and centre pressure of the fibre-reinforced disc and of its matrix alone (run
# from the results folder: history.csv is the fibre run, isotropic_unconfined/history.csv the
# other one).
set datafile separator ","
set datafile columnheaders
set terminal pngcairo size 900,1100 noenhanced
set grid
fibre = "history.csv"
matrix = "isotropic_unconfined/history.csv"
A0 = 2.25                   # reference platen area of the eighth model [mm^2]
# drained equilibrium (uniaxial stress of the solid law, tests/verification/app/fibre_unconfined_test.cpp)
eq_fibre = 0.0545713
eq_matrix = 0.0533121
set output "fibre_reinforced_unconfined.png"
set multiplot layout 3,1 title "Unconfined compression, 10 % in 20 s then held: fibre-reinforced vs isotropic biphasic disc"
set xlabel "time [s]"
set ylabel "platen stress -R_z/A_0 [MPa]"
set key right top
set xrange [0:600]
plot fibre using 1:(-column("disc.zmax.Rz [N]")/A0) with linespoints pt 7 ps 0.5 lw 2 title "matrix + fibres along x and y", \
     matrix using 1:(-column("disc.zmax.Rz [N]")/A0) with linespoints pt 7 ps 0.5 lw 2 title "matrix alone"
set logscale x
set xrange [1:50000]
set logscale y
set ylabel "platen stress -R_z/A_0 [MPa] (log)"
plot fibre using 1:(-column("disc.zmax.Rz [N]")/A0) with lines lw 2 title "matrix + fibres", \
     matrix using 1:(-column("disc.zmax.Rz [N]")/A0) with lines lw 2 title "matrix alone", \
     eq_fibre with lines dt 2 lc 1 title "drained equilibrium 0.05457 MPa, fibres (closed form)", \
     eq_matrix with lines dt 2 lc 2 title "drained equilibrium 0.05331 MPa, matrix (closed form)"
unset logscale y
set ylabel "fluid pressure at the centre [MPa]"
plot fibre using 1:(column("centre.fluid_pressure [MPa]")) with lines lw 2 title "matrix + fibres", \
     matrix using 1:(column("centre.fluid_pressure [MPa]")) with lines lw 2 title "matrix alone"
unset multiplot
