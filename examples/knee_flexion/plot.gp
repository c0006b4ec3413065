# Knee flexion: the load through the joint, the contact area and the flexion angle, and the
# fluid pressure of the tibial cartilage at the contact, against time. Run from the results
# folder:   gnuplot -c plot.gp
set datafile separator ","
set datafile columnheaders
set terminal pngcairo size 900,600 noenhanced
set grid
set key inside right center

set output "knee_forces.png"
set title "The load through the joint (per mm depth): applied, contact, tibia"
set xlabel "time [s]"
set ylabel "force [N]"
set logscale x
set xrange [0.01:*]
plot "history.csv" using "time [s]":(-column("femur.Fy [N]")) with linespoints lw 2 \
       title "load on the femur", \
     "history.csv" using "time [s]":"contact1.Fy [N]" with lines lw 2 dt 2 \
       title "contact force on the femoral cartilage", \
     "history.csv" using "time [s]":(-column("tibial.bone.Ry [N]")) with lines lw 2 dt 3 \
       title "reaction of the tibia"

set output "knee_contact.png"
set title "Contact area (per mm depth) and flexion angle"
set ylabel "contact area [mm^2]"
set y2label "flexion [rad]"
set y2tics
plot "history.csv" using "time [s]":"contact1.area [mm^2]" with linespoints lw 2 \
       title "contact area", \
     "history.csv" using "time [s]":"knee.angle [rad]" axes x1y2 with lines lw 2 dt 2 \
       title "flexion (right axis)"
unset y2tics
unset y2label

set output "knee_pressure.png"
set title "Fluid pressure of the tibial cartilage at the contact (Donnan osmotic part included)"
set ylabel "p [MPa]"
plot "history.csv" using "time [s]":"plateau.fluid_pressure [MPa]" with linespoints lw 2 \
       title "tibial plateau, x = 8 mm"
