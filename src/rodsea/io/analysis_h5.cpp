#include "rodsea/io/analysis_h5.hpp"

#include "rodsea/io/atomic_file.hpp"
#include "rodsea/io/detail/hdf5.hpp"

namespace rodsea {

namespace {

// The group at `path` ("a/b/c"), created where missing; returns it open.
h5::Handle group_at(const h5::File& f, const std::string& path) {
    h5::Handle group = h5::open_group(f, f.id(), "/");
    std::size_t start = 0;
    while (start < path.size()) {
        const std::size_t slash = std::min(path.find('/', start), path.size());
        const std::string name = path.substr(start, slash - start);
        group = h5::exists(group.get(), name) ? h5::open_group(f, group.get(), name)
                                              : h5::create_group(f, group.get(), name);
        start = slash + 1;
    }
    return group;
}

void write_array(const h5::File& f, const std::string& observable, const AnalysisDataset& d) {
    const std::size_t slash = d.path.rfind('/');
    const std::string parent = slash == std::string::npos ? "" : d.path.substr(0, slash);
    const std::string name = slash == std::string::npos ? d.path : d.path.substr(slash + 1);
    const h5::Handle group = group_at(f, parent);
    const std::vector<hsize_t> dims(d.dims.begin(), d.dims.end());
    if (const auto* v = std::get_if<std::vector<double>>(&d.values))
        h5::write_dataset(f, group.get(), name, *v, dims, d.unit);
    else if (const auto* w = std::get_if<std::vector<float>>(&d.values))
        h5::write_compressed_dataset(f, group.get(), name, *w, dims, d.unit);
    else
        h5::write_dataset(f, group.get(), name, std::get<std::vector<std::int32_t>>(d.values), dims,
                          d.unit);
    const h5::Handle set = h5::open_dataset(f, group.get(), name);
    h5::write_attribute(f, set.get(), "description", d.description);
    h5::write_attribute(f, set.get(), "observable", observable);
}

}  // namespace

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
            for (const AnalysisDataset& d : a.datasets)
                write_array(f, a.observable, d);
        }
        f.close();
    });
}

}  // namespace rodsea
