# The one look of every slipfield plot (compiled into the binary by the
# Makefile; edit here).  pngcairo is byte-stable; noenhanced keeps case ids
# like field_exact literal instead of subscripting them.
set terminal pngcairo size 900,600 font 'DejaVu Sans,11' noenhanced
set termoption noenhanced
set grid lc rgb '#dddddd'
set key outside bottom center horizontal noenhanced
set border lw 1.2
set linetype 1 lc rgb '#1f77b4' lw 2 pt 7 ps 0.8
set linetype 2 lc rgb '#d62728' lw 2 pt 5 ps 0.8
set linetype 3 lc rgb '#2ca02c' lw 2 pt 9 ps 0.8
set linetype 4 lc rgb '#9467bd' lw 2 pt 11 ps 0.8
set linetype 5 lc rgb '#ff7f0e' lw 2 pt 13 ps 0.8
set linetype 6 lc rgb '#8c564b' lw 2 pt 3 ps 0.8
