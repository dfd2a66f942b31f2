"""Figures of `rodsea plot` (docs/plots.md), drawn with Debian's matplotlib.

common         errors, reading rodsea's CSV files, figure sizes and atomic PNG writing
inputs         what INPUT is: a run's analysis or a table with one row per run
run_figures    one run's analysis: order, C(t), flocks, g(r), g(r,θ), G(r,θ), medium flow
table_figures  several runs: P, Σ, ... vs φ_a and vs D_r, and the phase diagram
"""
