# Top displacement under creep against the series solution (from the results folder).
set datafile separator ","
set datafile columnheaders
set terminal pngcairo size 900,600 noenhanced
set grid
set key right top
exact = system("dirname " . ARG0) . "/exact.csv"
set output "biphasic_creep_top.png"
set title "Biphasic confined creep: surface displacement"
set xlabel "time [s]"
set ylabel "u_z at the top [mm]"
plot "history.csv" using 1:(column("top.uz [mm]")) with lines lw 2 title "trifem (40 cells)", \
     exact using 1:2 with points pt 6 title "series (Terzaghi / Mow et al. 1980)"
