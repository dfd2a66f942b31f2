#!/usr/bin/python3
"""Reference labels for rodsea's DBSCAN (src/rodsea/analysis/dbscan.cpp), used by
tests/test_dbscan.cpp to check it label for label against scikit-learn.

Reads points (one "x y" or "x y z" per line; z is ignored) from IN, runs
sklearn.cluster.DBSCAN on the minimum-image distance matrix of a box periodic in x and y,
and writes one label per line to OUT (-1 noise, clusters 0, 1, ... in sklearn's numbering).

    dbscan_reference.py IN OUT --eps E --min-samples M --box LX LY
"""
import argparse

import numpy as np
from sklearn.cluster import DBSCAN


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("input")
    parser.add_argument("output")
    parser.add_argument("--eps", type=float, required=True)
    parser.add_argument("--min-samples", type=int, required=True)
    parser.add_argument("--box", type=float, nargs=2, required=True, metavar=("LX", "LY"))
    args = parser.parse_args()

    xy = np.atleast_2d(np.loadtxt(args.input, dtype=float))[:, :2]
    box = np.array(args.box)
    d = xy[:, None, :] - xy[None, :, :]
    d -= box * np.rint(d / box)  # minimum image; rint rounds half to even, as std::nearbyint
    distance = np.sqrt((d * d).sum(axis=-1))
    labels = DBSCAN(eps=args.eps, min_samples=args.min_samples,
                    metric="precomputed").fit_predict(distance)
    np.savetxt(args.output, labels, fmt="%d")


if __name__ == "__main__":
    main()
