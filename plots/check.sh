#!/usr/bin/env bash
# plots/check.sh OUT STEM... - checks what `make plots` made in OUT.
#
# Every figure exists as a non-empty PNG (the PNG signature) and SVG (a
# closing </svg>); every data file in OUT/data has exactly the header it
# should, the same number of fields on every row, at least one row, and no
# NaN or infinity anywhere; and the fitted slopes say what the theory says:
# plain pi within 0.05 of -1/2, stratified pi steeper than -0.7, and the
# chi-square p-values of the correct sampler uniform (Kolmogorov-Smirnov),
# those of the wrong one all below 1e-3; the balance heuristic's weights of
# the path figures sum to 1; and no figure or data file is older than the
# script, style, data or program that makes it (with a negative control
# that must be caught). Exit status 1 on any failure.
set -uo pipefail

out=$1
shift
data=$out/data
fails=0
fail() {
    echo "plots-check: FAIL: $*"
    fails=$((fails + 1))
}

rms_cols=program,method,n,seeds,rms_error,rel_rms_error,mean_stderr,mean_variance,exact
slope_cols=program,method,slope,intercept,points,n_min,n_max
# The header each data file must have.
header_of() {
    case $1 in
    pi_convergence.csv | integrate_x_sq_convergence.csv | cos_cubed_variance.csv | \
        convergence_rates.csv | qmc_convergence.csv) echo "$rms_cols" ;;
    rates_*.csv) echo "$rms_cols" ;;
    *_slopes.csv) echo "$slope_cols" ;;
    sphere_scatter.csv) echo method,x,y,z ;;
    qmc_points.csv) echo method,i,x,y ;;
    hemisphere_mappings.csv) echo mapping,x,y,z ;;
    cos_theta_histograms.csv) echo sampler,param,bin_lo,bin_hi,count,density,expected_density ;;
    chi2_cells.csv) echo i,j,cos_lo,cos_hi,phi_lo,phi_hi,observed,expected,diff_sd ;;
    chi2_pvalues.csv) echo case,seed,n,chi2,dof,p ;;
    efficiency.csv) echo problem,method,n,variance,exact,cpu_seconds,seconds_per_sample,seconds_to_1pct ;;
    sphere_patch.csv | area_solid_angle.csv | onb_frames.csv | disc_mappings.csv | \
        hemisphere_uniform_cosine.csv | sphere_light_cone.csv | cone_cap.csv | bdpt_strategies.csv)
        echo curve,x,y,z ;;
    mixture_lobes.csv) echo curve,angle_deg,density ;;
    bdpt_weights.csv) echo height,w_s0,w_s1,w_s2,w_s3,sum ;;
    *) echo "" ;;
    esac
}
expected_data="$(printf '%s.csv\n' "$@") pi_convergence_slopes.csv integrate_x_sq_convergence_slopes.csv
cos_cubed_variance_slopes.csv convergence_rates_slopes.csv qmc_convergence_slopes.csv"

figures=0
for s in "$@"; do
    png=$out/$s.png svg=$out/$s.svg
    if [ ! -s "$png" ] || [ "$(head -c 8 "$png" | od -An -tx1 | tr -d ' \n')" != 89504e470d0a1a0a ]; then
        fail "$png missing, empty or not a PNG"
    else
        figures=$((figures + 1))
    fi
    if [ ! -s "$svg" ] || ! grep -q '</svg>' "$svg"; then
        fail "$svg missing, empty or not an SVG"
    else
        figures=$((figures + 1))
    fi
done

files=0
for f in $expected_data; do
    [ -f "$data/$f" ] || fail "$data/$f missing"
done
for path in "$data"/*.csv; do
    [ -f "$path" ] || continue
    f=$(basename "$path")
    want=$(header_of "$f")
    if [ -z "$want" ]; then
        fail "$path: a data file no figure declares"
        continue
    fi
    msg=$(awk -F, -v want="$want" '
        NR == 1 { if ($0 != want) { print "header is \"" $0 "\", expected \"" want "\""; exit 1 }
                  nf = NF; next }
        NF != nf { print "line " NR " has " NF " fields, expected " nf; exit 1 }
        { for (c = 1; c <= NF; c++) {
              v = tolower($c)
              if (v ~ /^[-+]?(nan|inf|infinity)$/ || v ~ /^-?nan\(/) {
                  print "line " NR " column " c " is " $c; exit 1 } } }
        END { if (NR < 2) { print "no data rows"; exit 1 } }' "$path")
    if [ -n "$msg" ]; then fail "$path: $msg"; else files=$((files + 1)); fi
done

# slope PROGRAM METHOD: the fitted slope from a *_slopes.csv file, or "".
slope() {
    awk -F, -v p="$2" -v m="$3" '$1 == p && $2 == m { print $3 }' "$data/$1"
}
check_slope() { # file program method awk-condition description
    local s
    s=$(slope "$1" "$2" "$3")
    if [ -z "$s" ]; then
        fail "$1: no fitted slope for $2 $3"
    elif awk -v s="$s" "BEGIN { exit !($4) }"; then
        echo "plots-check: $2 $3 slope $s ($5): ok"
    else
        fail "$2 $3 slope $s, expected $5"
    fi
}
if [ -f "$data/pi_convergence_slopes.csv" ]; then
    check_slope pi_convergence_slopes.csv pi plain 's > -0.55 && s < -0.45' "-1/2 within 0.05"
    check_slope pi_convergence_slopes.csv pi stratified 's < -0.7' "steeper than -0.7"
fi
# Quasi-Monte Carlo in 2D: Monte Carlo stays at -1/2 (within 0.15: the quick
# run fits 8 seeds over 2.4 decades, a slope sd of about 0.05); scrambled
# Sobol on the smooth integrand is steeper than -1.2 (theory -3/2); on the
# discontinuous pi indicator no method reaches -1 (theory -3/4).
if [ -f "$data/qmc_convergence_slopes.csv" ]; then
    check_slope qmc_convergence_slopes.csv smooth mc 's > -0.65 && s < -0.35' "-1/2 within 0.15"
    check_slope qmc_convergence_slopes.csv smooth sobol-owen 's < -1.2' "steeper than -1.2"
    check_slope qmc_convergence_slopes.csv pi sobol-owen 's > -0.95' "flatter than -0.95"
fi

if [ -f "$data/chi2_pvalues.csv" ]; then
    # Both samplers must have been tested, at the same seeds: an empty side
    # would make the checks below pass vacuously.
    n_ok=$(awk -F, '$1 == "correct"' "$data/chi2_pvalues.csv" | wc -l)
    n_bad=$(awk -F, '$1 == "wrong"' "$data/chi2_pvalues.csv" | wc -l)
    if [ "$n_ok" -lt 20 ] || [ "$n_ok" -ne "$n_bad" ]; then
        fail "chi2_pvalues.csv: $n_ok correct and $n_bad wrong rows (need >= 20 each, equal)"
    fi
    # Kolmogorov-Smirnov distance of the correct p-values from U(0,1);
    # sqrt(n) D > 1.95 has probability 0.001 under uniformity.
    ks=$(awk -F, '$1 == "correct" { print $6 }' "$data/chi2_pvalues.csv" | sort -g |
        awk '{ p[NR] = $1 } END { d = 0; for (i = 1; i <= NR; i++) {
                a = i / NR - p[i]; b = p[i] - (i - 1) / NR
                if (a > d) d = a; if (b > d) d = b }
              printf "%.3f", d * sqrt(NR) }')
    if awk -v k="$ks" 'BEGIN { exit !(k < 1.95) }'; then
        echo "plots-check: correct sampler p-values uniform, sqrt(n) D = $ks < 1.95: ok"
    else
        fail "correct sampler p-values not uniform: sqrt(n) D = $ks"
    fi
    big=$(awk -F, '$1 == "wrong" && $6 >= 1e-3' "$data/chi2_pvalues.csv" | wc -l)
    if [ "$big" -eq 0 ]; then
        echo "plots-check: wrong sampler rejected at every seed (p < 1e-3): ok"
    else
        fail "wrong sampler has $big p-values >= 1e-3"
    fi
fi

# The balance heuristic's weights of a path sum to 1 over its strategies
# (render/bdpt.h): on every path of the family and on the drawn one.
if [ -f "$data/bdpt_weights.csv" ]; then
    bad=$(awk -F, 'NR > 1 && ($6 < 1 - 1e-9 || $6 > 1 + 1e-9)' "$data/bdpt_weights.csv" | wc -l)
    rows=$(($(wc -l <"$data/bdpt_weights.csv") - 1))
    if [ "$bad" -eq 0 ] && [ "$rows" -ge 100 ]; then
        echo "plots-check: MIS weights sum to 1 on all $rows paths of bdpt_weights: ok"
    else
        fail "bdpt_weights.csv: $bad of $rows rows whose weights do not sum to 1 (or fewer than 100 rows)"
    fi
fi
if [ -f "$data/bdpt_strategies.csv" ]; then
    sum=$(awk -F, '$1 ~ /^weight:/ { s += $2; n++ } END { if (n == 4) printf "%.12f", s }' "$data/bdpt_strategies.csv")
    if awk -v s="$sum" 'BEGIN { exit !(s != "" && s > 1 - 1e-9 && s < 1 + 1e-9) }'; then
        echo "plots-check: the drawn path's four weights sum to $sum: ok"
    else
        fail "bdpt_strategies.csv: the four weights sum to '$sum', not 1"
    fi
fi

# No stale figure: every figure is newer than its gnuplot script, the
# shared style and its data, and every data file newer than its data script
# and the programs that script calls as $(prog NAME) (plots/Makefile.inc
# makes them depend on exactly these, so an older file means a dependency
# make did not know about). stale_in OUT BIN STEM... prints one line each.
stale_in() {
    local o=$1 b=$2 st f p
    shift 2
    for st in "$@"; do
        for f in "$o/$st.png" "$o/$st.svg"; do
            [ -f "$f" ] || continue
            for p in "plots/$st.gp" plots/style.gp "$o/data/$st.csv"; do
                [ -f "$p" ] && [ "$p" -nt "$f" ] && echo "$f is older than $p"
            done
        done
        f=$o/data/$st.csv
        [ -f "$f" ] || continue
        for p in "plots/data_$st.sh" $(sed -n 's/.*$(prog \([A-Za-z0-9_-]*\)).*/\1/p' "plots/data_$st.sh" 2>/dev/null | sed "s#^#$b/#"); do
            [ -f "$p" ] && [ "$p" -nt "$f" ] && echo "$f is older than $p"
        done
    done
    return 0
}
bin=$(dirname "$out")/bin
stale=$(stale_in "$out" "$bin" "$@")
if [ -z "$stale" ]; then
    echo "plots-check: no figure or data file older than what makes it: ok"
else
    while read -r line; do fail "stale: $line"; done <<<"$stale"
fi
# Its negative control: a copy of one figure and its data dated 2000 must be
# reported as older than its script, its data script and its program.
if [ -f "$out/disc_mappings.png" ] && [ -f "$data/disc_mappings.csv" ]; then
    tmpd=$(mktemp -d)
    mkdir -p "$tmpd/data"
    cp "$out/disc_mappings.png" "$tmpd/" && cp "$data/disc_mappings.csv" "$tmpd/data/"
    touch -d '2000-01-01' "$tmpd/disc_mappings.png" "$tmpd/data/disc_mappings.csv"
    caught=$(stale_in "$tmpd" "$bin" disc_mappings)
    rm -rf "$tmpd"
    if grep -q 'older than plots/disc_mappings.gp' <<<"$caught" &&
        grep -q 'older than plots/data_disc_mappings.sh' <<<"$caught" &&
        grep -q "older than $bin/figure_geometry" <<<"$caught"; then
        echo "plots-check: negative control: a figure and data older than their script and program are caught: ok"
    else
        fail "negative control: stale copies of disc_mappings not caught ($caught)"
    fi
fi

if [ "$fails" -eq 0 ]; then
    echo "plots-check: $figures figures and $files data files in $out: all ok"
else
    echo "plots-check: $fails failures in $out"
    exit 1
fi
