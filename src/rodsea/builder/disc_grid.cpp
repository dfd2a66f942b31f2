#include "rodsea/builder/disc_grid.hpp"

#include <algorithm>
#include <cmath>

namespace rodsea {

namespace {

// x in [−L, 2L) to [0, L): the discs of a body whose centre is in the box.
double wrap_once(double x, double side) {
    if (x < 0.0) {
        x += side;
        return x < side ? x : 0.0;  // −1e−17 + side rounds to side
    }
    return x >= side ? x - side : x;
}

}  // namespace

DiscGrid::DiscGrid(const std::vector<std::uint32_t>& species, const std::vector<Footprint>& feet,
                   const Box& box, double clearance)
    : feet_(feet), species_(species), lx_(box.lx), ly_(box.ly), clearance_(clearance) {
    std::uint32_t discs = 0;
    for (const std::uint32_t s : species_) {
        first_disc_.push_back(discs);
        discs += static_cast<std::uint32_t>(feet[s].size());
        max_radius_ = std::max(max_radius_, feet[s].max_radius);
    }
    first_disc_.push_back(discs);
    // No bodies: one cell, rather than cells as narrow as the clearance.
    const double width = max_radius_ > 0.0 ? 2.0 * max_radius_ + clearance : lx_ + ly_;
    nx_ = std::max(1, static_cast<int>(std::floor(lx_ / width)));
    ny_ = std::max(1, static_cast<int>(std::floor(ly_ / width)));
    inv_wx_ = static_cast<double>(nx_) / lx_;
    inv_wy_ = static_cast<double>(ny_) / ly_;
    pad_ = static_cast<int>(std::ceil(width * std::max(inv_wx_, inv_wy_))) + 1;
    for (int i = -pad_; i < std::max(nx_, ny_) + pad_; ++i) {
        if (i < nx_ + pad_) {
            const int w = (i % nx_ + nx_) % nx_;
            wrap_x_.push_back(w);
            shift_x_.push_back(lx_ * static_cast<double>((i - w) / nx_));
        }
        if (i < ny_ + pad_) {
            const int w = (i % ny_ + ny_) % ny_;
            wrap_y_.push_back(w);
            shift_y_.push_back(ly_ * static_cast<double>((i - w) / ny_));
        }
    }
    // Room for twice the mean occupancy; a crowded cell doubles every cell's room (rarely).
    const double mean = static_cast<double>(discs) / (static_cast<double>(nx_) * ny_);
    capacity_ = std::max(8, static_cast<int>(std::ceil(2.0 * mean)) + 4);
    count_.assign(static_cast<size_t>(nx_) * ny_, 0);
    slots_.resize(count_.size() * static_cast<size_t>(capacity_));
    cell_of_disc_.resize(discs);
    slot_of_disc_.resize(discs);
}

DiscGrid::DiscGrid(const PlanarBodies& bodies, const std::vector<Footprint>& feet, const Box& box,
                   double clearance)
    : DiscGrid(bodies.species, feet, box, clearance) {
    for (std::uint32_t b = 0; b < bodies.size(); ++b)
        insert_body(b, bodies.x[b], bodies.y[b], bodies.angle[b]);
}

void DiscGrid::insert_body(std::uint32_t b, double x, double y, double angle) {
    place_discs(b, x, y, angle);
    for (std::uint32_t k = 0; k < trial_.size(); ++k) {
        const Disc& d = trial_[k];
        insert(first_disc_[b] + k, cell_of(d.x, d.y), {d.x, d.y, d.r, b, first_disc_[b] + k});
    }
}

int DiscGrid::cell_of(double x, double y) const {
    const int cx = std::min(nx_ - 1, static_cast<int>(x * inv_wx_));
    const int cy = std::min(ny_ - 1, static_cast<int>(y * inv_wy_));
    return cy * nx_ + cx;
}

void DiscGrid::insert(std::uint32_t disc, int cell, const Slot& slot) {
    if (count_[cell] == static_cast<std::uint32_t>(capacity_)) grow();
    const std::uint32_t k = count_[cell]++;
    slots_[static_cast<size_t>(cell) * capacity_ + k] = slot;
    cell_of_disc_[disc] = cell;
    slot_of_disc_[disc] = k;
}

void DiscGrid::grow() {
    const int old = capacity_;
    capacity_ *= 2;
    std::vector<Slot> slots(count_.size() * static_cast<size_t>(capacity_));
    for (size_t c = 0; c < count_.size(); ++c)
        std::copy_n(slots_.begin() + static_cast<std::ptrdiff_t>(c * old), count_[c],
                    slots.begin() + static_cast<std::ptrdiff_t>(c * capacity_));
    slots_.swap(slots);
}

void DiscGrid::place_discs(std::uint32_t b, double x, double y, double angle) {
    const Footprint& f = feet_[species_[b]];
    const double c = std::cos(angle), s = std::sin(angle);
    trial_.resize(f.size());
    for (size_t k = 0; k < f.size(); ++k) {
        trial_[k] = {wrap_once(x + c * f.along[k] - s * f.across[k], lx_),
                     wrap_once(y + s * f.along[k] + c * f.across[k], ly_), f.radius[k]};
    }
}

bool DiscGrid::trial(std::uint32_t b, double x, double y, double angle) {
    place_discs(b, x, y, angle);
    for (const Disc& d : trial_) {
        const double reach = d.r + max_radius_ + clearance_;
        // Raw indices offset by pad_; past the edges they are periodic images.
        const int ix0 = static_cast<int>(std::floor((d.x - reach) * inv_wx_)) + pad_;
        const int ix1 = static_cast<int>(std::floor((d.x + reach) * inv_wx_)) + pad_;
        const int iy0 = static_cast<int>(std::floor((d.y - reach) * inv_wy_)) + pad_;
        const int iy1 = static_cast<int>(std::floor((d.y + reach) * inv_wy_)) + pad_;
        for (int iy = iy0; iy <= iy1; ++iy) {
            const double sy = shift_y_[iy];
            const int row = wrap_y_[iy] * nx_;
            for (int ix = ix0; ix <= ix1; ++ix) {
                const double sx = shift_x_[ix];
                const int cell = row + wrap_x_[ix];
                const Slot* slot = &slots_[static_cast<size_t>(cell) * capacity_];
                const Slot* end = slot + count_[cell];
                for (; slot != end; ++slot) {
                    if (slot->body == b) continue;
                    const double dx = slot->x + sx - d.x, dy = slot->y + sy - d.y;
                    const double contact = slot->r + d.r + clearance_;
                    if (dx * dx + dy * dy < contact * contact) return false;
                }
            }
        }
    }
    return true;
}

void DiscGrid::commit(std::uint32_t b) {
    for (std::uint32_t k = 0; k < trial_.size(); ++k) {
        const std::uint32_t disc = first_disc_[b] + k;
        const Disc& d = trial_[k];
        const int from = cell_of_disc_[disc], to = cell_of(d.x, d.y);
        Slot* cell = &slots_[static_cast<size_t>(from) * capacity_];
        if (from == to) {
            cell[slot_of_disc_[disc]].x = d.x;
            cell[slot_of_disc_[disc]].y = d.y;
            continue;
        }
        // Swap-remove: the cell's last disc takes the freed slot.
        const std::uint32_t last = --count_[from];
        const std::uint32_t freed = slot_of_disc_[disc];
        if (freed != last) {
            cell[freed] = cell[last];
            slot_of_disc_[cell[freed].disc] = freed;
        }
        insert(disc, to, {d.x, d.y, d.r, b, disc});
    }
}

}  // namespace rodsea
