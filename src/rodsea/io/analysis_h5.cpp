#include "rodsea/io/analysis_h5.hpp"

#include "rodsea/io/atomic_file.hpp"
#include "rodsea/io/detail/hdf5.hpp"

namespace rodsea {

void write_analysis_h5(const std::filesystem::path& path, const std::string& run,
                       const std::vector<AnalysisArrays>& arrays) {
    replace_file_atomically(path, [&](const std::filesystem::path& tmp) {
        h5::File f = h5::File::create(tmp);
        h5::write_attribute(f, f.id(), "creator", std::string("rodsea ") + RODSEA_VERSION);
        h5::write_attribute(f, f.id(), "run", run);
        h5::Handle maps = h5::create_group(f, f.id(), "maps");
        h5::Handle labels = h5::create_group(f, f.id(), "labels");
        for (const AnalysisArrays& a : arrays) {
            for (const AnalysisMap& m : a.maps) {
                h5::Handle g = h5::create_group(f, maps.get(), m.name);
                h5::write_attribute(f, g.get(), "description", m.description);
                h5::write_attribute(f, g.get(), "observable", a.observable);
                const hsize_t nr = m.r_edges.size() - 1, nt = m.theta_edges.size() - 1;
                h5::write_dataset(f, g.get(), "value", m.values, {nr, nt}, m.unit);
                h5::write_dataset(f, g.get(), "r_edges", m.r_edges, {nr + 1}, "mm");
                h5::write_dataset(f, g.get(), "theta_edges", m.theta_edges, {nt + 1}, "rad");
            }
            for (const AnalysisLabels& l : a.labels) {
                h5::Handle g = h5::create_group(f, labels.get(), l.name);
                h5::write_attribute(f, g.get(), "description", l.description);
                const hsize_t frames = l.times.size(), n = l.bodies.size();
                h5::write_dataset(f, g.get(), "value", l.labels, {frames, n});
                std::vector<std::int32_t> bodies(l.bodies.begin(), l.bodies.end());
                h5::write_dataset(f, g.get(), "body", bodies, {n});
                h5::write_dataset(f, g.get(), "time", l.times, {frames}, "s");
            }
        }
        f.close();
    });
}

}  // namespace rodsea
