#pragma once
// The ε → D_r map of a polar rod, read from the calibration.csv that `rodsea calibrate` writes,
// for the gap and time step of a run: what lets a config give the paper's control parameter D_r
// instead of ε (docs/model.md §3).
#include <filesystem>
#include <vector>

#include "rodsea/config/config_file.hpp"
#include "rodsea/engine/physics/plate_noise.hpp"

namespace rodsea {

class CalibrationTable {
  public:
    struct Point {
        double epsilon = 0.0;  // 1/mm
        double d_r = 0.0;      // rad²/s
    };

    // The polar_rod rows measured at this gap (mm), dt (s) and noise mode, in increasing ε. A
    // table without a noise_mode column (written before there were two modes) holds add rows.
    // Throws FileError when the file cannot be read or is not a calibration table, and
    // InvalidParameter (naming noise.calibration_table) when it has fewer than two such rows or
    // D_r does not increase with ε.
    static CalibrationTable read(const std::filesystem::path& path, double gap, double dt,
                                 physics::NoiseMode mode);

    // ε for `d_r`, interpolated linearly between the measured points. Throws InvalidParameter
    // naming noise.rotational_diffusion with the table's range when d_r lies outside it.
    double epsilon_for(double d_r) const;

    const std::vector<Point>& points() const { return points_; }

  private:
    std::vector<Point> points_;
    std::filesystem::path path_;
};

// The lookup the config needs for noise.rotational_diffusion: reads the table at the run's gap,
// dt and noise mode and interpolates ε.
EpsilonLookup calibration_table_lookup();

}  // namespace rodsea
