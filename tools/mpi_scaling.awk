# tools/mpi_scaling.awk - the efficiency model of docs/scaling.md, from the
# ray segments of each row of the book scene (tests/mpi/rowcost.c, CSV
# "row,segments") and three measured figures: gbs (GB/s rank 0 receives),
# rate (paths/s of one rank), start (seconds mpirun adds at K = 1).
#
# Rank r of K renders rows r, r + K, ...; its time is its share of the
# segments. Efficiency E(K) = T(1) / (K T(K)) with
#   T(K) = busiest rank's work / rate + image bytes / gbs + start,
# where the image bytes (64 per pixel) reach rank 0 once, at the end. The
# balance factor alone is mean / max of the ranks' work. A 2160-row image
# reuses the 600-row profile, each of its rows taking the cost of the
# 600-row image's row at the same height (the scene is the same).
NR > 1 { c[n++] = $2; total += $2 }
function busiest(rows, k,    r, y, s, m) {
    m = 0
    for (r = 0; r < k; r++) {
        s = 0
        for (y = r; y < rows; y += k)
            s += cost[y]
        if (s > m)
            m = s
    }
    return m
}
function profile(rows,    y, t) {
    t = 0
    for (y = 0; y < rows; y++) {
        cost[y] = c[int(y * n / rows)]
        t += cost[y]
    }
    return t
}
function efficiency(rows, width, spp, k,    t, paths, one, tk) {
    t = profile(rows)
    paths = rows * width * spp
    one = paths / rate
    tk = busiest(rows, k) / t * paths / rate + rows * width * 64 / (gbs * 1e9) + start
    return one / (k * tk)
}
END {
    split("1 2 3 4 8 16 32 64 100 150 200 300 600", ks, " ")
    printf "%-6s %14s %14s\n", "K", "balance 600", "balance 2160"
    for (i = 1; i in ks; i++) {
        k = ks[i]
        t6 = profile(600); b6 = t6 / k / busiest(600, k)
        t2 = profile(2160); b2 = t2 / k / busiest(2160, k)
        printf "%-6d %14.4f %14.4f\n", k, b6, b2
    }
    printf "\nlargest K up to which the efficiency stays > 90%% (rate %.3g paths/s per rank, rank 0 receives %.3g GB/s, start %.2f s):\n",
        rate, gbs, start
    printf "%-16s %8s %8s %8s\n", "image", "100 spp", "1000 spp", "10000 spp"
    split("600x600 3840x2160", imgs, " ")
    for (j = 1; j <= 2; j++) {
        split(imgs[j], wh, "x")
        printf "%-16s", imgs[j]
        split("100 1000 10000", spps, " ")
        for (s = 1; s <= 3; s++) {
            best = 1
            # "Stays above": the last K before the first that falls below.
            for (k = 1; k <= wh[2]; k++) {
                if (efficiency(wh[2], wh[1], spps[s], k) <= 0.9)
                    break
                best = k
            }
            printf " %8d", best
        }
        printf "\n"
    }
}
