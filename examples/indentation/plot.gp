# Indenter force relaxation, fluid pressure on the indenter axis, and contact pressure and
# fluid pressure along the radius y = 0 under the indenter. Run from the results folder:
#   gnuplot -c plot.gp
set datafile separator ","
set datafile columnheaders
set terminal pngcairo size 900,600 noenhanced
set grid
set key outside right

set output "indentation_force.png"
set key inside right center
set title "Indenter force (whole layer: 4 x the quarter model) and indentation depth"
set xlabel "time [s]"
set ylabel "force [N]"
set y2label "indentation depth [mm]"
set y2tics
set logscale x
plot "history.csv" using "time [s]":(-4 * column("indenter.Fz [N]")) with linespoints lw 2 \
       title "indenter force", \
     "history.csv" using "time [s]":(4 * column("layer.bottom.Rz [N]")) with lines dt 2 lw 2 \
       title "bone reaction", \
     "history.csv" using "time [s]":(-column("indenter.uz [mm]")) axes x1y2 with lines lw 1 \
       title "depth (right axis)"
unset y2tics
unset y2label
set key outside right

set output "indentation_pressure.png"
set title "Fluid pressure on the indenter axis (Donnan osmotic part included)"
set ylabel "p [MPa]"
plot "history.csv" using "time [s]":"top.fluid_pressure [MPa]" with linespoints lw 2 \
       title "under the indenter (z = 1.5 mm)", \
     "history.csv" using "time [s]":"middle.fluid_pressure [MPa]" with linespoints lw 2 \
       title "mid-depth (z = 0.75 mm)", \
     "history.csv" using "time [s]":"bone.fluid_pressure [MPa]" with linespoints lw 2 \
       title "at the bone (z = 0)"
unset logscale x

# the contact surface files of the end of the ramp and of the relaxation
wanted = "2 5 10 100 1000"
selected = ""
labels = ""
files = system("ls contact1_surface_*.csv")
do for [f in files] {
  stats f using 1 nooutput
  do for [w in wanted] {
    if (abs(STATS_min - w) < 1e-9) {
      selected = selected . " " . f
      labels = labels . " " . sprintf("t=%g_s", STATS_min)
    }
  }
}
n = words(selected)

# the points of the radius y = 0 of each selected file, one data set each (index i - 1)
radial(c, name) = sprintf("set table %s append; plot word(selected, i) using \"X [mm]\":(%s) with table if (abs(column(\"Y [mm]\")) < 1e-12); unset table; set print %s append; print \"\"; print \"\"; unset print", name, c, name)
$Traction << EOD
EOD
$Potential << EOD
EOD
do for [i=1:n] {
  eval radial('-column("contact_traction [MPa]")', "$Traction")
  eval radial('column("fluid_chemical_potential [MPa]")', "$Potential")
}
set datafile separator whitespace # the tables are written with blanks
set datafile nocolumnheaders
set xlabel "radius x along y = 0 (reference) [mm]"
set xrange [0:2]

set output "indentation_contact_pressure.png"
set title "Contact pressure under the indenter along the radius"
set ylabel "-t [MPa]"
plot for [i=1:n] $Traction index (i - 1) with linespoints lw 2 title word(labels, i)

set output "indentation_surface_potential.png"
set title "Water chemical potential on the layer surface along the radius (bath = 0)"
set ylabel "mu_w [MPa]"
plot for [i=1:n] $Potential index (i - 1) with linespoints lw 2 title word(labels, i)
