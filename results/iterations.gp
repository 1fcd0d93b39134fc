# gnuplot script written by agjk-bench (run from the output directory)
set terminal pngcairo size 1100,420 font ',10'
set output 'iterations.png'
set multiplot layout 1,2 title 'Ellipsoids: iterations vs signed distance (mean, bars = std)'
set xtics ('-0.1' 0, '-1e-2' 1, '-1e-3' 2, '-1e-4' 3, '1e-4' 4, '1e-3' 5, '1e-2' 6, '0.1' 7, '0.5' 8, '1' 9, '2.5' 10, '5' 11) rotate by -45
set ylabel 'iterations'; set grid; set key top left
set title 'distance'
plot 'iterations.dat' index 0 using 1:3:4 with yerrorlines title 'GJK', '' index 1 using 1:3:4 with yerrorlines title 'Nesterov'
set title 'Boolean'
plot 'iterations.dat' index 2 using 1:3:4 with yerrorlines title 'GJK', '' index 3 using 1:3:4 with yerrorlines title 'Nesterov'
unset multiplot
