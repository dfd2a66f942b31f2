#pragma once
// The system of the LAMMPS race (bench/race/in.vibrods, after ../shared/peers/lammps): rods of
// 7 equal spheres, 0.8 mm across and 4.5 mm long, lying on a grid of 5 mm × 1.2 mm cells, each
// along ±x within 5° and tilted up to 4° out of the plane, at mid-gap between plates 1.2 mm apart
// that vibrate at 200 Hz with Γ = 7; μ = 0.05 and e = 0.3 for every collision. 25 × 80 cells
// give the peer's 2000 rods in a 125 mm × 96 mm box.
#include <cstdint>
#include <string>

#include "rodsea/scenes/scenes.hpp"

namespace rodsea::race {

inline constexpr double kRodLength = 4.5;       // mm
inline constexpr double kSphereDiameter = 0.8;  // mm
inline constexpr int kSpheresPerRod = 7;
inline constexpr double kCellX = 5.0;       // mm
inline constexpr double kCellY = 1.2;       // mm
inline constexpr double kGap = 1.2;         // mm
inline constexpr double kDensity = 8000.0;  // kg/m³, for the LAMMPS file only

Scene race_scene(int cells_x, int cells_y, std::uint64_t seed);

// The scene's rods as a LAMMPS data file (atom_style sphere, SI units, one molecule per rod) with
// the plates' travel as the z bounds, written atomically. Throws std::runtime_error on failure.
void write_lammps_data(const Scene& scene, const std::string& path);

}  // namespace rodsea::race
