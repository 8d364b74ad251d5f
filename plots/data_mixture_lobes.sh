# plots/data_mixture_lobes.sh BIN DATA - the cosine, light and mixture
# densities of examples/mixture.c along one plane (see
# examples/figure_geometry.c). mixture_lobes.csv: what `figure_geometry
# mixture` prints.
source "$(dirname "$0")/lib.sh"
p=$(prog figure_geometry)
"$p" mixture  >"$DATA/mixture_lobes.csv.tmp" || die "figure_geometry mixture failed"
publish mixture_lobes.csv
