set terminal pngcairo size 1000,650 noenhanced font 'DejaVu Sans,11'
set output 'docs/data/accuracy/cornell-error-vs-time.png'
set title 'Error against time to C=0.99: cornell (/work/main/assets/cornell.gltf)'
set xlabel 'seconds to C = 0.99'
set ylabel 'relative RMS error of B'
set grid
set key outside right top
set logscale x
set logscale y
plot '-' with linespoints title 'plane r3 cell 0.1', '-' with linespoints title 'plane r5 cell 0.1', '-' with linespoints title 'hemicube cell 0.1', '-' with linespoints title 'plane r3 cell 0.05', '-' with linespoints title 'plane r5 cell 0.05', '-' with linespoints title 'hemicube cell 0.05', '-' with lines lw 3 lc rgb 'black' title 'Pareto front'
0.018116841 0.0271214215
0.021845512 0.0185622208
0.034196619 0.0179697693
0.058817191 0.0173413616
e
0.019937346 0.0278006968
0.022441609 0.0233090684
0.03690183 0.0164785755
0.021056578 0.0135895957
e
0.01636171 0.0147845067
0.019472063 0.0112286085
0.029930923 0.0101472999
0.115653897 0.0105504562
e
0.018313821 0.02330405
0.014781948 0.0217642
0.033009257 0.0190456557
0.048052242 0.0188485308
e
0.039462564 0.0183627283
0.018719968 0.0211294865
0.03951311 0.0173049171
0.116661536 0.0154599734
e
0.06527259 0.0166159148
0.075537632 0.0138007506
0.049906168 0.0131580035
0.218276078 0.0131644476
e
0.014781948 0.0217642
0.01636171 0.0147845067
0.019472063 0.0112286085
0.029930923 0.0101472999
e
