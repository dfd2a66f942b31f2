#pragma once
// The neighbour lists' skin (mm), on the CPU (VerletPairList) and on the GPU alike. Bodies move
// micrometres per step, so a list lasts hundreds of steps; a thicker skin lasts longer but lists
// more pairs to check every step. Since the rebuild runs on every thread, 0.05 mm (a sixteenth of
// the 0.8 mm spheres; a rebuild every 150-800 steps) beats 0.1 mm by 5-25 % per step on every
// benchmark system, and 0.03 mm gains at most 5 % more while rebuilding twice as often, a share
// that grows with the threads (docs/performance.md, fifth pass). The trajectory does not depend
// on it: a list holds every touching pair either way, in the same order.
namespace rodsea {

inline constexpr double kVerletSkin = 0.05;

}  // namespace rodsea
