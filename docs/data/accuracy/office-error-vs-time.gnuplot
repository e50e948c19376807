set terminal pngcairo size 1000,650 noenhanced font 'DejaVu Sans,11'
set output 'docs/data/accuracy/office-error-vs-time.png'
set title 'Error against time to C=0.99: office'
set xlabel 'seconds to C = 0.99'
set ylabel 'relative RMS error of B'
set grid
set key outside right top
set logscale x
set logscale y
plot '-' with linespoints title 'plane r3 cell 0.381', '-' with linespoints title 'plane r5 cell 0.381', '-' with linespoints title 'hemicube cell 0.381', '-' with lines lw 3 lc rgb 'black' title 'Pareto front'
0.993056709 0.0507707959
0.732648994 0.049213522
0.907534028 0.0457930089
1.39738314 0.0450460941
e
0.817672743 0.0487101726
2.44763994 0.0381020956
2.02236161 0.03295716
3.44014156 0.031186785
e
3.94811537 0.0206800828
4.47998986 0.0180887281
5.11074266 0.0163226909
6.36482762 0.0162185068
e
0.732648994 0.049213522
0.817672743 0.0487101726
0.907534028 0.0457930089
1.39738314 0.0450460941
2.02236161 0.03295716
3.44014156 0.031186785
3.94811537 0.0206800828
4.47998986 0.0180887281
5.11074266 0.0163226909
6.36482762 0.0162185068
e
