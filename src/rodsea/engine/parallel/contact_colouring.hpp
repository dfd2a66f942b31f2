#pragma once
// Colours a step's contacts so that no two of one colour share a body (a plate is no body): the
// contacts of a colour then take their impulses at once, and the colours one after another make
// a Gauss–Seidel sweep. Jones–Plassmann: rounds of ColourRound until no contact waits; every
// contact gets the smallest colour its neighbours left free, so the colours number about the
// most contacts around one contact, whatever the system's size.
//
// Also keeps which contacts touch each body (the incidence), which the noise reads too.
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "rodsea/engine/parallel/kernels.hpp"

namespace rodsea::parallel {

// How many bits a radix sort reads for keys below `distinct`.
inline int key_bits(std::uint64_t distinct) {
    int bits = 1;
    while (bits < 32 && (std::uint64_t{1} << bits) < distinct)
        ++bits;
    return bits;
}

template <class Executor>
class ContactColouring {
  public:
    template <class T>
    using Array = typename Executor::template Array<T>;

    // Contacts [0, body_contacts) are between bodies, the rest with a plate; bodies number
    // `bodies`; `rank` orders the contacts (RankContactsInTheirSystem). Afterwards colour c's
    // contacts are order()[range(c).first ..].
    void colour(Executor& exec, const Array<Contact>& contacts, const std::uint32_t* rank,
                std::uint32_t count, std::uint32_t body_contacts, std::uint32_t bodies) {
        reserve(count, bodies);
        const std::uint32_t incidences = body_contacts + count;  // 2B + P
        exec.launch(count, ListIncidences{contacts.data(), body_contacts, incidence_body_.data(),
                                          incidence_contact_.data()});
        exec.sort_by_key(incidence_body_, incidence_contact_, incidences, key_bits(bodies));
        exec.fill(incidence_start_, bodies, 0u);
        exec.fill(incidence_end_, bodies, 0u);
        exec.launch(incidences, MarkRuns{incidence_body_.data(), incidences,
                                         incidence_start_.data(), incidence_end_.data()});
        exec.fill(coloured_in_, count, -1);
        for (int round = 0;; ++round) {
            // Each round colours at least the highest-ranked waiting contact.
            if (static_cast<std::uint32_t>(round) > count)
                throw std::logic_error("rodsea: the contact colouring did not finish");
            exec.write(waiting_, 0, 0);
            exec.launch(count, ColourRound{contacts.data(), rank, incidence(), round,
                                           colour_.data(), coloured_in_.data(), waiting_.data()});
            if (exec.read(waiting_, 0) == 0) break;
        }
        colours_ = count == 0 ? 0 : exec.max_of(colour_, count) + 1;
        const auto colours = static_cast<std::uint32_t>(colours_);
        exec.launch(count, KeyContactsByColour{colour_.data(), colour_key_.data(), order_.data()});
        exec.sort_by_key(colour_key_, order_, count, key_bits(colours));
        colour_start_.resize(colours);
        colour_end_.resize(colours);
        exec.launch(count,
                    MarkRuns{colour_key_.data(), count, colour_start_.data(), colour_end_.data()});
        exec.download(colour_start_, colours, host_start_);
        exec.download(colour_end_, colours, host_end_);
    }

    int colours() const { return colours_; }
    struct Range {
        std::uint32_t first, count;
    };
    Range range(int colour) const {
        const auto c = static_cast<std::size_t>(colour);
        return {host_start_[c], host_end_[c] - host_start_[c]};
    }
    const std::uint32_t* order() const { return order_.data(); }
    const Array<int>& colour_of() const { return colour_; }
    Incidence incidence() const {
        return {incidence_contact_.data(), incidence_start_.data(), incidence_end_.data()};
    }

  private:
    void reserve(std::uint32_t count, std::uint32_t bodies) {
        waiting_.resize(1);
        if (incidence_start_.size() < bodies) {
            incidence_start_.resize(bodies);
            incidence_end_.resize(bodies);
        }
        if (colour_.size() >= count) return;
        const std::size_t room = count + count / 4 + 64;
        colour_.resize(room);
        coloured_in_.resize(room);
        colour_key_.resize(room);
        order_.resize(room);
        incidence_body_.resize(2 * room);
        incidence_contact_.resize(2 * room);
    }

    Array<std::uint32_t> incidence_body_, incidence_contact_, incidence_start_, incidence_end_;
    Array<int> colour_, coloured_in_, waiting_;
    Array<std::uint32_t> colour_key_, order_, colour_start_, colour_end_;
    std::vector<std::uint32_t> host_start_, host_end_;
    int colours_ = 0;
};

}  // namespace rodsea::parallel
