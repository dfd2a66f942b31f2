#pragma once
// analysis.h5 of `rodsea analyze` (docs/analysis.md): the maps (value [r][θ] with its bin edges)
// and the per-frame labels, with descriptions and units as attributes.
#include <cstdint>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

namespace rodsea {

// A polar map, values[r_bin * theta_bins + theta_bin]: /maps/<name>/{value, r_edges, theta_edges}.
struct AnalysisMap {
    std::string name;
    std::string description;
    std::string unit;
    std::vector<double> r_edges;      // mm
    std::vector<double> theta_edges;  // rad
    std::vector<double> values;
};

// Per-frame integer labels of a fixed set of bodies (flock labels), [frames][bodies]:
// /labels/<name>/{value, body, time}.
struct AnalysisLabels {
    std::string name;
    std::string description;
    std::vector<std::uint32_t> bodies;  // body indices in the trajectory
    std::vector<double> times;          // s
    std::vector<std::int32_t> labels;
};

// Any other array, at `path` ("fields/series/polar/area_fraction": groups made as needed), with
// its shape. float values are stored compressed in single precision (time series of maps).
struct AnalysisDataset {
    std::string path;
    std::string description;
    std::string unit;
    std::vector<std::uint64_t> dims;
    std::variant<std::vector<double>, std::vector<float>, std::vector<std::int32_t>> values;
};

// One observable's maps, labels and datasets, written with the observable's name as an
// attribute.
struct AnalysisArrays {
    std::string observable;
    const std::vector<AnalysisMap>& maps;
    const std::vector<AnalysisLabels>& labels;
    const std::vector<AnalysisDataset>& datasets;
};

// Writes the file atomically. Throws FileError naming it on any failure.
void write_analysis_h5(const std::filesystem::path& path, const std::string& run,
                       const std::vector<AnalysisArrays>& arrays);

}  // namespace rodsea
