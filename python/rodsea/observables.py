"""Compute objects in freud's style over the C++ observables of `rodsea analyze`."""
import numpy as np

from . import _rodsea


class OrderParameters:
    """P = |<(cos θ, sin θ)>| and S = |<(cos 2θ, sin 2θ)>| of a set of angles (rad)."""

    def compute(self, angles):
        angles = np.asarray(angles, dtype=float)
        self.P = _rodsea.order_parameter(angles, 1)
        self.S = _rodsea.order_parameter(angles, 2)
        return self


class Flocks:
    """DBSCAN flocks (the paper's clusters): labels (-1 for none), sizes, the largest (N_m)."""

    def __init__(self, eps=2.25, min_samples=3):
        self.eps, self.min_samples = eps, min_samples

    def compute(self, box, positions):
        self.labels = _rodsea.dbscan(box, np.asarray(positions, dtype=float), self.eps,
                                     self.min_samples)
        flocked = self.labels[self.labels >= 0]
        self.sizes = np.bincount(flocked) if flocked.size else np.zeros(0, dtype=int)
        self.largest = int(self.sizes.max()) if self.sizes.size else 0
        return self


class TimeCorrelation:
    """C(t) = <cos m(θ(t0 + t) - θ(t0))> of a (frames, bodies) array of unwrapped angles taken
    `interval` seconds apart, and D_r fitted to -ln C = m² D_r t where C >= floor."""

    def __init__(self, m=1, max_lag=None, floor=0.2):
        self.m, self.max_lag, self.floor = m, max_lag, floor

    def compute(self, angles, interval):
        angles = np.asarray(angles, dtype=np.float32)
        max_lag = self.max_lag if self.max_lag is not None else angles.shape[0] // 2
        self.C = _rodsea.orientation_autocorrelation(angles, self.m, max_lag)
        self.lags = np.arange(len(self.C)) * interval
        self.D_r = _rodsea.rotational_diffusion(self.C, interval, self.m, self.floor)
        return self
