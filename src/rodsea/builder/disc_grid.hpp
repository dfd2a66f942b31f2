#pragma once
// A periodic grid of the discs of flat bodies that follows Monte Carlo moves: a body's discs are
// re-binned when it moves, so trial moves test against the current neighbours without rebuilds.
// (PeriodicGrid2D is built whole and is the wrong tool for moving one body at a time.)
#include <cstdint>
#include <vector>

#include "rodsea/builder/footprint.hpp"
#include "rodsea/builder/planar_bodies.hpp"
#include "rodsea/engine/parameters.hpp"

namespace rodsea {

class DiscGrid {
  public:
    // An empty grid for bodies of the given species (body b has species[b]). Cells are at least
    // one widest disc pair plus the clearance wide, so a disc's neighbours lie in the cells its
    // reach touches (at most 3 × 3).
    DiscGrid(const std::vector<std::uint32_t>& species, const std::vector<Footprint>& feet,
             const Box& box, double clearance);
    // A grid holding every body as placed.
    DiscGrid(const PlanarBodies& bodies, const std::vector<Footprint>& feet, const Box& box,
             double clearance);

    // Adds body b (not yet in the grid) without checking it.
    void insert_body(std::uint32_t b, double x, double y, double angle);

    // Whether body b placed at (x, y) with its axis at `angle` keeps each of its discs at least
    // the clearance from every disc of every other body, in the plane with the minimum image.
    // Remembers the trial's discs for commit.
    bool trial(std::uint32_t b, double x, double y, double angle);

    // Moves body b's discs (already in the grid) to those of its last trial.
    void commit(std::uint32_t b);

  private:
    struct Slot {
        double x, y, r;
        std::uint32_t body, disc;
    };
    struct Disc {
        double x, y, r;
    };
    int cell_of(double x, double y) const;
    void insert(std::uint32_t disc, int cell, const Slot& slot);
    void grow();
    void place_discs(std::uint32_t b, double x, double y, double angle);

    const std::vector<Footprint>& feet_;
    std::vector<std::uint32_t> species_;     // of each body
    std::vector<std::uint32_t> first_disc_;  // of each body, into cell_of_disc_ / slot_of_disc_
    double lx_, ly_, clearance_, max_radius_ = 0.0;
    int nx_ = 1, ny_ = 1;
    double inv_wx_ = 1.0, inv_wy_ = 1.0;
    // Raw cell index i (from −pad_ to n + pad_) → cell index and the shift that brings that
    // cell's discs next to the querying disc: the periodic images without a division per cell.
    int pad_ = 1;
    std::vector<int> wrap_x_, wrap_y_;
    std::vector<double> shift_x_, shift_y_;
    int capacity_ = 8;                  // slots per cell
    std::vector<std::uint32_t> count_;  // discs in each cell
    std::vector<Slot> slots_;           // cell c owns slots [c capacity_, (c + 1) capacity_)
    std::vector<int> cell_of_disc_;
    std::vector<std::uint32_t> slot_of_disc_;  // index within its cell
    std::vector<Disc> trial_;                  // the discs of the last trial
};

}  // namespace rodsea
