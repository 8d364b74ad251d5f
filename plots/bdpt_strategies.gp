# plots/bdpt_strategies.gp - the four ways bidirectional path tracing can
# build one path of three segments. Data: bdpt_strategies.csv
# (plots/data_bdpt_strategies.sh, examples/figure_paths.c path): the
# "lambert" Cornell box's quads, a path the renderer's calls built (camera
# ray, cosine bounce, a point on the lamp) with x0 on the lamp and x3 the
# camera, and the weight rt_bdpt_mis_weight gives each strategy. Panel s
# has s light vertices (orange), 4 - s camera vertices (blue) and the
# shadow ray that joins them (dashed); s = 0 is the camera's path finding
# the lamp by itself.
W = 1100; H = 1000
load 'plots/style.gp'
f = datadir.'/bdpt_strategies.csv'
array PX[4]; array PY[4]; array PZ[4]; array WS[4]
do for [i = 0:3] {
    stats f using (sel(1, sprintf('x%d', i)) ? $2 : NaN) nooutput; PX[i + 1] = STATS_max
    stats f using (sel(1, sprintf('x%d', i)) ? $3 : NaN) nooutput; PY[i + 1] = STATS_max
    stats f using (sel(1, sprintf('x%d', i)) ? $4 : NaN) nooutput; PZ[i + 1] = STATS_max
    stats f using (sel(1, sprintf('weight:%d', i)) ? $2 : NaN) nooutput; WS[i + 1] = STATS_max
}
# The camera is 800 units in front of the room: its vertex is drawn where
# the segment x_2 - x_3 crosses z = -300, so that the room stays large.
zc = -300.0; tc = (zc - PZ[3]) / (PZ[4] - PZ[3])
PX[4] = PX[3] + tc * (PX[4] - PX[3]); PY[4] = PY[3] + tc * (PY[4] - PY[3]); PZ[4] = zc
unset key; unset grid
set view 68, 28, 0.95
set view equal xyz
# gnuplot's vertical axis is the room's y (up), its depth axis the room's z.
set xrange [-20:575]; set yrange [-310:575]; set zrange [-20:575]
unset border; unset xtics; unset ytics; unset ztics
names = '"the camera path reaches the lamp" "next-event estimation: lamp point joined" "one step from each end, joined" "light path joined to the camera"'
set multiplot layout 2, 2 margins 0.02, 0.98, 0.0, 0.86 spacing 0.02, 0.09 title "{/:Bold Four strategies, one path: camera (x_3), floor (x_2), wall (x_1), lamp (x_0)}\nblue: the camera subpath; orange: the light subpath; dashed: the shadow ray that joins them.\nThe weights are rt\\_bdpt\\_mis\\_weight's balance heuristic; they sum to 1" font ',12'
do for [s = 0:3] {
    unset arrow; unset label
    do for [i = 0:2] {
        # edge x_i - x_{i+1}: light subpath if i + 1 < s, the join if i + 1 == s, else camera
        if (i + 1 < s) { set arrow from PX[i + 1], PZ[i + 1], PY[i + 1] to PX[i + 2], PZ[i + 2], PY[i + 2] nohead lt 2 lw 3 }
        if (i + 1 == s) { set arrow from PX[i + 1], PZ[i + 1], PY[i + 1] to PX[i + 2], PZ[i + 2], PY[i + 2] nohead lt 7 lw 2 dt 2 }
        if (i + 1 > s) { set arrow from PX[i + 1], PZ[i + 1], PY[i + 1] to PX[i + 2], PZ[i + 2], PY[i + 2] nohead lt 1 lw 3 }
    }
    do for [i = 0:3] {
        if (i == 3) { set label 'x_3 (toward the camera)' at PX[4], PZ[4], PY[4] right offset -0.8, -0.9 point pt 7 ps 0.8 font ',11' } \
        else { set label sprintf('x_%d', i) at PX[i + 1], PZ[i + 1], PY[i + 1] offset 0.8, 0.6 point pt 7 ps 0.8 font ',12' }
    }
    set title sprintf("s = %d, t = %d: %s\nweight %.4f", s, 4 - s, word(names, s + 1), WS[s + 1]) font ',12'
    splot f using (sel(1, 'room') ? $2 : NaN):4:3 with lines lc rgb '#aaaaaa' lw 1, \
          f using (sel(1, 'lamp') ? $2 : NaN):4:3 with lines lt 5 lw 3
}
unset multiplot
