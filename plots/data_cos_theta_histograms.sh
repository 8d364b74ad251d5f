# plots/data_cos_theta_histograms.sh BIN DATA - histograms of sampled
# cos theta against the analytic marginal density.
# cos_theta_histograms.csv: sampler,param,bin_lo,bin_hi,count,density,
# expected_density for cosine, Phong n = 40 and GGX alpha = 0.5 and 0.25:
# 5 10^5 directions each (quick: 5 10^4) from `warp sample`, 50 bins of
# cos theta in [0, 1]. expected_density is the analytic marginal averaged
# over the bin, (F(hi) - F(lo)) / width, from the closed-form CDFs of
# cos theta: c^2 (cosine), c^(n+1) (Phong), a^2 c^2 / (1 + c^2 (a^2 - 1))
# (GGX, the D(h) cos theta_h density of half vectors).
source "$(dirname "$0")/lib.sh"
w=$(prog warp)
n=500000
[ "$PLOTS_QUICK" = 1 ] && n=50000
out=$DATA/cos_theta_histograms.csv.tmp
echo sampler,param,bin_lo,bin_hi,count,density,expected_density >"$out"
seed=31
while read -r name key value; do
    args=()
    [ "$key" = - ] || args=(--param "$key=$value")
    "$w" sample "$name" "${args[@]}" --n "$n" --seed $((seed++)) |
        awk -v s="$name" -v par="$value" -v bins=50 '
        function cdf(c) {
            if (s == "cosine") return c * c
            if (s == "phong") return c ^ (par + 1)
            a2 = par * par
            return a2 * c * c / (1 + c * c * (a2 - 1))
        }
        { b = int($3 * bins); if (b >= bins) b = bins - 1; if (b < 0) b = 0; count[b]++; total++ }
        END {
            for (b = 0; b < bins; b++) {
                lo = b / bins; hi = (b + 1) / bins
                printf "%s,%s,%.4f,%.4f,%d,%.6e,%.6e\n", s, par, lo, hi, count[b],
                       count[b] / (total * (hi - lo)), (cdf(hi) - cdf(lo)) / (hi - lo)
            }
        }' >>"$out"
done <<'LIST'
cosine - -
phong n 40
ggx alpha 0.5
ggx alpha 0.25
LIST
publish cos_theta_histograms.csv
