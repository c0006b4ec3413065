# Contact traction and gap along the interface at the end of the patch test (run from the
# results folder): the exact solution is t = -q = -0.1 MPa and g = 0 at every slave node.
set datafile separator ","
set datafile columnheaders
set terminal pngcairo size 900,600 noenhanced
set grid
set output "contact_patch_traction.png"
set title "Contact patch test: slave-node traction along the interface (t = 1 s)"
set xlabel "current x [mm]"
set ylabel "contact traction t [MPa]"
set y2label "gap g [mm]"
set y2tics
set yrange [-0.12:0]
set key left top
plot "contact1_surface_0002.csv" using (column("x [mm]")):(column("contact_traction [MPa]")) \
       with linespoints pt 7 ps 1.3 lw 2 title "t (both-surfaces integration)", \
     -0.1 with lines dt 2 lw 2 title "exact t = -q", \
     "contact1_surface_0002.csv" using (column("x [mm]")):(column("contact_gap [mm]")) \
       axes x1y2 with points pt 6 ps 1.3 title "gap g (right axis)"
