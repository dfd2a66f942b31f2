#pragma once
// Stage 3 of the CPU step: every sphere–sphere overlap between different bodies (minimum image in
// x, y) and every sphere poking through the base or the lid. Contact points sit in the middle
// of the overlap. Sphere pairs come from a Verlet list. Body contacts are listed in the order
// of their (sphere i < sphere j) pairs, then plate contacts in sphere order, so the list is a
// function of the state alone: not of the list's age, nor of the number of threads.
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "rodsea/engine/body_state.hpp"
#include "rodsea/engine/cpu/sphere_table.hpp"
#include "rodsea/engine/physics/contact.hpp"
#include "rodsea/engine/physics/step_context.hpp"
#include "rodsea/engine/species_table.hpp"
#include "rodsea/neighbors/verlet_pair_list.hpp"

namespace rodsea::cpu {

struct ContactSearchStats {
    size_t body_contacts = 0;
    size_t plate_contacts = 0;
    double max_overlap_fraction = 0.0;  // overlap / smaller radius, largest in this step
    size_t gross_overlaps = 0;          // contacts deeper than kGrossOverlapFraction
};

class ContactFinder {
  public:
    explicit ContactFinder(double skin = kVerletSkin) : pairs_(skin) {}

    // `travel`: a bound on how far any sphere moved in the plane since the last call (mm), for
    // the Verlet list (VerletPairList::update).
    ContactSearchStats find(const SphereTable& spheres, BodyView bodies,
                            const SpeciesTable& species, const StepContext& step,
                            std::vector<Contact>& out, int threads,
                            double travel = std::numeric_limits<double>::infinity());
    // As find(), for the bodies `awake` (ascending) only: a pair with a body marked in
    // `coasting` is skipped, as are the plates' contacts of such a body. The same contacts in the
    // same order as find() where the coasting bodies touch nothing.
    ContactSearchStats find_awake(const SphereTable& spheres, BodyView bodies,
                                  const SpeciesTable& species, const StepContext& step,
                                  std::span<const std::uint32_t> awake,
                                  std::span<const std::uint8_t> coasting, std::vector<Contact>& out,
                                  int threads, double travel);
    const VerletPairList& pairs() const { return pairs_; }
    std::uint64_t pair_list_builds() const { return pairs_.builds(); }

    // The overlaps one chunk of the search found: the deepest, over the smaller radius, and how
    // many were gross.
    struct Depth {
        double deepest = 0.0;
        size_t gross = 0;
        void add(double overlap_fraction);
    };

  private:
    // Empties one chunk of body contacts, of plate contacts and of depths per thread.
    void start_chunks(int threads);
    // `out` becomes the chunks' body contacts, then their plate contacts, in chunk order.
    ContactSearchStats gather_chunks(std::vector<Contact>& out) const;
    // Appends the chunks to `out`, which holds `at` contacts, and returns how many they had.
    static size_t gather(const std::vector<std::vector<Contact>>& chunks, std::vector<Contact>& out,
                         size_t at);

    VerletPairList pairs_;
    // Per thread: its chunk's body contacts and plate contacts, and their overlaps.
    std::vector<std::vector<Contact>> body_chunks_, plate_chunks_;
    std::vector<Depth> depth_;
};

}  // namespace rodsea::cpu
