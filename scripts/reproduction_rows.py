"""The reproduction's first row (Fig. 1c / 3a: φ_p = 0.05, σ = 3.125, D_r = 0) run from several
seeds: one series table per seed, in one place, so that the figures
(scripts/reproduction_figures.py) and the error-bar check (scripts/error_bar_check.py) read the
same seeds. A seed added here is drawn and checked at once. Paths are relative to the
repository. The figures leave out a table not yet committed; the error-bar check refuses it,
and leaves out (and counts) one whose run has not reached its window's end.
"""
DATA = "data/reproduction"
FIG1C_SERIES = f"{DATA}/fig1c-phi_p0.05-long"
REPLICATES63 = f"{DATA}/finite-size/replicates63"

# The 38 mm box (18 polar rods), 180 s per run: {φ_a as written in the file names: [table per
# seed]}. Seed 1 of 0.05-0.50 is fig1c-phi_a*-scale0.15.toml's; the further seeds are
# replicates38.toml's (0.05, 0.20), replicates38-0.35-0.50.toml's (seed 2) and
# replicates38-0.35-0.50-seed3.toml's. The dense end (0.65, 0.80)
# is fig1c-dense-38mm.toml's, continued to 270 s, its second seed's, stopped at 209 s, and its
# third seed's, fig1c-dense-38mm-seed3.toml's, run to 180 s; the row is compared over the window
# every run has.
REPLICATES38_SEEDS = {"0.05": (2, 3), "0.20": (2, 3), "0.35": (2, 3), "0.50": (2, 3)}
# The dense end's seeds by file-name suffix.
DENSE38_SEEDS = {"0.65": ("", ".seed2", ".seed3"), "0.80": ("", ".seed2", ".seed3")}
ROW38 = {
    phi: [f"{DATA}/finite-size/fig1c-phi_a{phi}-scale0.15.series.csv"] + [
        f"{DATA}/finite-size/replicates38/medium.area_fraction={phi.rstrip('0')}.seed{k}.series.csv"
        for k in seeds]
    for phi, seeds in REPLICATES38_SEEDS.items()
} | {
    phi: [f"{DATA}/fig1c-dense-38mm/medium.area_fraction={phi.rstrip('0')}{seed}.series.csv"
          for seed in seeds]
    for phi, seeds in DENSE38_SEEDS.items()
}


def seeds_1_and_2(folder, phi):
    """Seed 1's and seed 2's series tables of one φ_a, kept side by side in `folder`."""
    return [f"{DATA}/{folder}/medium.area_fraction={phi:g}{seed}.series.csv"
            for seed in ("", ".seed2")]


# The 63 mm box (50 polar rods): {φ_a: [table per seed]}. Seed 1 of 0.05 and 0.20 is the long
# campaign's, run on to 180 s; their further seeds are replicates63*.toml's. 0.50's third to
# fifth seeds are fig1c-mid-63mm-seed{3,4,5}.toml's, and 0.35's seeds 1 and 2
# fig1c-mid-63mm-0.35.toml's and fig1c-mid-63mm-0.35-seed2.toml's. A seed still running (listed
# here with its checkpoint kept to run it on) is drawn once it has two blocks past 60 s and
# checked once it reaches 180 s.
ROW63 = {
    0.05: [f"{FIG1C_SERIES}/medium.area_fraction=0.05_extended_to_180_s.series.csv"] + [
        f"{REPLICATES63}/medium.area_fraction=0.05.seed{k}.series.csv" for k in range(2, 7)],
    0.20: [f"{FIG1C_SERIES}/medium.area_fraction=0.2_extended_to_180_s.series.csv"] + [
        f"{REPLICATES63}/medium.area_fraction=0.2.seed{k}.series.csv" for k in (2, 3)],
    0.35: seeds_1_and_2("fig1c-mid-63mm", 0.35),
    0.50: seeds_1_and_2("fig1c-mid-63mm", 0.5) + [
        f"{DATA}/fig1c-mid-63mm/medium.area_fraction=0.5.seed{k}.series.csv" for k in (3, 4, 5)],
    0.65: seeds_1_and_2("fig1c-dense-63mm", 0.65),
    0.80: seeds_1_and_2("fig1c-dense-63mm", 0.8),
}
