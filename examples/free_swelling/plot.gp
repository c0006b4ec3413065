# Swelling history of the cube corner against the closed-form equilibrium (from the results folder).
set datafile separator ","
set datafile columnheaders
set terminal pngcairo size 900,600 noenhanced
set grid
set logscale x
set key right bottom
set output "free_swelling_stretch.png"
set title "Free swelling from the Donnan state: stretch of the cube"
set xlabel "time [s]"
set ylabel "stretch [-]"
# root of E(l^2-1)/(2l) = Pi(J = l^3), SVK (docs/theory/reference-solutions.md §R4.4)
lambda = 1.17354   # root of E(l^2-1)/(2l) = Pi(J = l^3), SVK (docs/theory/reference-solutions.md §R4.4)
plot "history.csv" using 1:(1+column("corner.ux [mm]")) with linespoints lw 2 title "trifem (corner u_x + 1)", \
     lambda with lines dt 2 lw 2 title "closed-form equilibrium 1.17354"
