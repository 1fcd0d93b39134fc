# gnuplot script written by agjk-bench (run from the output directory)
set terminal pngcairo size 1100,450 font ',10'
set output 'work-precision.png'
set multiplot layout 1,2 title 'Work-precision: median |d - d_{ref}| vs median time, tolerance 1e-2 ... 1e-12 (error 0 drawn at 1e-17)'
set logscale xy; set grid; set format y '10^{%L}'
set xlabel 'median time per query (us)'; set ylabel 'median error'
set key top right font ',8'
set title 'ellipsoids'
plot 'work-precision.dat' index 0 using 2:3 with linespoints title 'FW', 'work-precision.dat' index 1 using 2:3 with linespoints title 'NESMINO', 'work-precision.dat' index 2 using 2:3 with linespoints title 'GJK', 'work-precision.dat' index 3 using 2:3 with linespoints title 'Nesterov', 'work-precision.dat' index 4 using 2:3 with linespoints title 'Nesterov-normalized', 'work-precision.dat' index 5 using 2:3 with linespoints title 'Polyak', 'work-precision.dat' index 6 using 2:3 with linespoints title 'Adaptive'
set title 'boxes'
plot 'work-precision.dat' index 7 using 2:3 with linespoints title 'FW', 'work-precision.dat' index 8 using 2:3 with linespoints title 'NESMINO', 'work-precision.dat' index 9 using 2:3 with linespoints title 'GJK', 'work-precision.dat' index 10 using 2:3 with linespoints title 'Nesterov', 'work-precision.dat' index 11 using 2:3 with linespoints title 'Nesterov-normalized', 'work-precision.dat' index 12 using 2:3 with linespoints title 'Polyak', 'work-precision.dat' index 13 using 2:3 with linespoints title 'Adaptive'
unset multiplot
