#pragma once
// What `rodsea calibrate` measures: one body kind over every combination of the listed ε, gaps
// and time steps, read from the [calibrate] table of a TOML file with every key checked.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "rodsea/calibration/single_body_experiment.hpp"

namespace rodsea {

struct CalibrationGrid {
    Species species;
    std::vector<double> epsilon{0.0};  // 1/mm
    physics::NoiseMode noise_mode = physics::NoiseMode::add;
    std::vector<double> gap{DriveParameters{}.gap};  // mm
    std::vector<double> dt{EngineParameters{}.dt};   // s
    int copies = 8;
    double duration = 2.0;  // s measured per copy
    double warmup = 0.2;    // s
    std::uint64_t seed = 1;

    // Every point, ε varying fastest: gap, then dt, then ε.
    std::vector<SingleBodyExperiment> experiments() const;
};

// Throws InvalidParameter naming `calibrate.<key>`, the value and the allowed range, or
// ConfigSyntaxError for TOML that does not parse.
CalibrationGrid parse_calibration_grid(std::string_view toml, const std::string& source);

// The keys of [calibrate] with unit, default and range, for --help.
extern const char* const kCalibrationKeysHelp;

}  // namespace rodsea
