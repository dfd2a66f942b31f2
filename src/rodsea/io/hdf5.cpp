#include "rodsea/io/detail/hdf5.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "rodsea/error.hpp"

namespace rodsea::h5 {

namespace {

// HDF5 prints its error stack to stderr by default; we turn each failure into one exception
// whose message carries the innermost cause (for a full disk: "errno = 28, No space left").
// HDF5 also closes files left open at exit; after a failed write (a full disk) that close
// crashes inside HDF5 1.10, so the library is told not to: every file we write is closed
// explicitly, and the failed ones are left for the next run to repair.
struct SilenceLibrary {
    SilenceLibrary() {
        H5dont_atexit();
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    }
};
const SilenceLibrary silence_library;

herr_t collect(unsigned n, const H5E_error2_t* e, void* data) {
    auto* out = static_cast<std::string*>(data);
    // The stack is walked from the innermost error outwards: the first one is the cause.
    if (n == 0 && e->desc != nullptr) *out = e->desc;
    return 0;
}

// HDF5's innermost message for a failed system call lists the call's raw arguments ("errno =
// 28, error message = 'No space left on device', ..., bytes actually written =
// 18446744073709551615"): the error number, in words, is what a user needs.
std::string in_words(const std::string& cause) {
    const std::size_t at = cause.find("errno = ");
    if (at == std::string::npos) return cause;
    const int error = std::atoi(cause.c_str() + at + 8);
    switch (error) {
        case ENOSPC:
            return "the disk is full (" + std::string(std::strerror(error)) + ")";
        case EDQUOT:
            return "the disk quota is exhausted (" + std::string(std::strerror(error)) + ")";
        case EFBIG:
            return "the file-size limit was reached (" + std::string(std::strerror(error)) + ")";
        case EIO:
            return "the device reported an input/output error (" +
                   std::string(std::strerror(error)) + ")";
        default:
            return "the system refused: " + std::string(std::strerror(error));
    }
}

std::string library_cause() {
    std::string cause;
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, collect, &cause);
    H5Eclear2(H5E_DEFAULT);
    return in_words(cause);
}

template <class Id>
hid_t check(Id id, const File& file, const std::string& what) {
    if (id < 0) fail(file.path(), what);
    return static_cast<hid_t>(id);
}

Handle dataspace(const std::vector<hsize_t>& dims, const std::vector<hsize_t>* max = nullptr) {
    return Handle(
        H5Screate_simple(static_cast<int>(dims.size()), dims.data(), max ? max->data() : nullptr));
}

void write_unit(const File& file, hid_t object, const std::string& unit) {
    if (!unit.empty()) write_attribute(file, object, "unit", unit);
}

template <class T>
void write_fixed(const File& file, hid_t parent, const std::string& name, hid_t file_type,
                 hid_t memory_type, const std::vector<T>& data, const std::vector<hsize_t>& dims,
                 const std::string& unit) {
    Handle space = dataspace(dims);
    Handle set(check(H5Dcreate2(parent, name.c_str(), file_type, space.get(), H5P_DEFAULT,
                                H5P_DEFAULT, H5P_DEFAULT),
                     file, "cannot create dataset " + name));
    if (!data.empty())
        check(H5Dwrite(set.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), file,
              "cannot write dataset " + name);
    write_unit(file, set.get(), unit);
}

template <class T>
std::vector<T> read_all(const File& file, hid_t parent, const std::string& name,
                        hid_t memory_type) {
    Handle set(check(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), file,
                     "no dataset " + name + " (not a rodsea file, or a damaged one)"));
    Handle space(H5Dget_space(set.get()));
    const hssize_t n = H5Sget_simple_extent_npoints(space.get());
    std::vector<T> data(static_cast<size_t>(n < 0 ? 0 : n));
    if (!data.empty())
        check(H5Dread(set.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), file,
              "cannot read dataset " + name);
    return data;
}

Handle string_type(size_t length) {
    Handle type(H5Tcopy(H5T_C_S1));
    H5Tset_size(type.get(), length == 0 ? 1 : length);
    H5Tset_strpad(type.get(), H5T_STR_NULLPAD);
    H5Tset_cset(type.get(), H5T_CSET_UTF8);
    return type;
}

}  // namespace

Handle& Handle::operator=(Handle&& other) noexcept {
    if (this != &other) {
        reset();
        id_ = other.id_;
        other.id_ = H5I_INVALID_HID;
    }
    return *this;
}

void Handle::reset() {
    if (id_ < 0) return;
    switch (H5Iget_type(id_)) {
        case H5I_FILE:
            H5Fclose(id_);
            break;
        case H5I_GROUP:
            H5Gclose(id_);
            break;
        case H5I_DATASET:
            H5Dclose(id_);
            break;
        case H5I_DATASPACE:
            H5Sclose(id_);
            break;
        case H5I_DATATYPE:
            H5Tclose(id_);
            break;
        case H5I_ATTR:
            H5Aclose(id_);
            break;
        case H5I_GENPROP_LST:
            H5Pclose(id_);
            break;
        default:
            break;
    }
    H5Eclear2(H5E_DEFAULT);
    id_ = H5I_INVALID_HID;
}

void fail(const std::filesystem::path& file, const std::string& what) {
    const std::string cause = library_cause();
    throw FileError(file.string(), cause.empty() ? what : what + " (" + cause + ")");
}

namespace {

// HDF5 locks a file it writes, so h5py could not look at a running simulation's trajectory. The
// writer flushes after every frame and is the only one to write, so readers may open it: the
// lock is dropped.
Handle unlocked_access() {
    Handle props(H5Pcreate(H5P_FILE_ACCESS));
    H5Pset_file_locking(props.get(), false, true);
    return props;
}

}  // namespace

File File::create(const std::filesystem::path& path) {
    const Handle access = unlocked_access();
    const hid_t id = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get());
    if (id < 0) fail(path, "cannot create HDF5 file");
    return File(Handle(id), path);
}

File File::open(const std::filesystem::path& path, bool writable) {
    if (!std::filesystem::exists(path)) throw FileError(path.string(), "no such file");
    const Handle access = unlocked_access();
    const hid_t id = H5Fopen(path.c_str(), writable ? H5F_ACC_RDWR : H5F_ACC_RDONLY, access.get());
    if (id < 0) fail(path, "not a readable HDF5 file (truncated or damaged?)");
    return File(Handle(id), path);
}

void File::flush() const {
    if (H5Fflush(id(), H5F_SCOPE_LOCAL) < 0) fail(path_, "cannot flush");
}

void File::close() {
    const hid_t id = handle_.get();
    if (id < 0) return;
    if (H5Fclose(id) >= 0) {
        handle_.release();
        return;
    }
    // A failed close leaves the id open in HDF5 1.10; closing it again can crash the library.
    handle_.release();
    fail(path_, "cannot close (the last writes failed)");
}

Handle create_group(const File& file, hid_t parent, const std::string& name) {
    return Handle(check(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                        file, "cannot create group " + name));
}

Handle open_group(const File& file, hid_t parent, const std::string& name) {
    return Handle(check(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), file,
                        "no group " + name + " (not a rodsea file, or a damaged one)"));
}

Handle open_dataset(const File& file, hid_t parent, const std::string& name) {
    return Handle(check(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), file,
                        "no dataset " + name + " (not a rodsea file, or a damaged one)"));
}

bool exists(hid_t parent, const std::string& path) {
    // H5Lexists needs every intermediate link to exist: walk the path one level at a time.
    std::string prefix;
    size_t start = 0;
    while (start <= path.size()) {
        const size_t slash = path.find('/', start);
        prefix = path.substr(0, slash);
        if (H5Lexists(parent, prefix.c_str(), H5P_DEFAULT) <= 0) {
            H5Eclear2(H5E_DEFAULT);
            return false;
        }
        if (slash == std::string::npos) break;
        start = slash + 1;
    }
    return true;
}

// String attributes are variable-length UTF-8, as h5py writes them: Python readers (h5py,
// MDAnalysis) then get str, not bytes, and MDAnalysis recognises the units.
void write_attribute(const File& file, hid_t object, const std::string& name,
                     const std::vector<std::string>& values, bool scalar) {
    Handle type(H5Tcopy(H5T_C_S1));
    H5Tset_size(type.get(), H5T_VARIABLE);
    H5Tset_cset(type.get(), H5T_CSET_UTF8);
    Handle space = scalar ? Handle(H5Screate(H5S_SCALAR)) : dataspace({values.size()});
    std::vector<const char*> pointers;
    for (const std::string& v : values)
        pointers.push_back(v.c_str());
    Handle attr(
        check(H5Acreate2(object, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
              file, "cannot create attribute " + name));
    check(H5Awrite(attr.get(), type.get(), pointers.data()), file,
          "cannot write attribute " + name);
}

void write_attribute(const File& file, hid_t object, const std::string& name,
                     const std::string& value) {
    write_attribute(file, object, name, std::vector<std::string>{value}, true);
}

void write_attribute(const File& file, hid_t object, const std::string& name,
                     const std::vector<std::string>& values) {
    write_attribute(file, object, name, values, false);
}

void write_attribute(const File& file, hid_t object, const std::string& name,
                     const std::vector<std::int32_t>& values) {
    Handle space = dataspace({values.size()});
    Handle attr(check(
        H5Acreate2(object, name.c_str(), H5T_STD_I32LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
        file, "cannot create attribute " + name));
    check(H5Awrite(attr.get(), H5T_NATIVE_INT32, values.data()), file,
          "cannot write attribute " + name);
}

// One number as a scalar attribute: stored as `file_type`, given as `memory_type`.
void write_scalar_attribute(const File& file, hid_t object, const std::string& name,
                            hid_t file_type, hid_t memory_type, const void* value) {
    Handle space(H5Screate(H5S_SCALAR));
    Handle attr(
        check(H5Acreate2(object, name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT),
              file, "cannot create attribute " + name));
    check(H5Awrite(attr.get(), memory_type, value), file, "cannot write attribute " + name);
}

void write_attribute(const File& file, hid_t object, const std::string& name, double value) {
    write_scalar_attribute(file, object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

void write_attribute(const File& file, hid_t object, const std::string& name, std::int32_t value) {
    write_scalar_attribute(file, object, name, H5T_STD_I32LE, H5T_NATIVE_INT32, &value);
}

void write_attribute(const File& file, hid_t object, const std::string& name, std::int64_t value) {
    write_scalar_attribute(file, object, name, H5T_STD_I64LE, H5T_NATIVE_INT64, &value);
}

std::int64_t read_int64_attribute(const File& file, hid_t object, const std::string& name) {
    Handle attr(check(H5Aopen(object, name.c_str(), H5P_DEFAULT), file, "no attribute " + name));
    Handle type(H5Aget_type(attr.get()));
    Handle space(H5Aget_space(attr.get()));
    if (H5Tget_class(type.get()) != H5T_INTEGER || H5Sget_simple_extent_npoints(space.get()) != 1)
        throw FileError(file.path().string(), "attribute " + name + " is not one integer");
    std::int64_t value = 0;
    check(H5Aread(attr.get(), H5T_NATIVE_INT64, &value), file, "cannot read attribute " + name);
    return value;
}

std::string read_string_attribute(const File& file, hid_t object, const std::string& name) {
    Handle attr(check(H5Aopen(object, name.c_str(), H5P_DEFAULT), file, "no attribute " + name));
    Handle type(H5Aget_type(attr.get()));
    if (H5Tget_class(type.get()) != H5T_STRING)
        throw FileError(file.path().string(), "attribute " + name + " is not a string");
    if (H5Tis_variable_str(type.get()) > 0) {
        Handle memory(H5Tcopy(H5T_C_S1));
        H5Tset_size(memory.get(), H5T_VARIABLE);
        H5Tset_cset(memory.get(), H5Tget_cset(type.get()));
        char* text = nullptr;
        check(H5Aread(attr.get(), memory.get(), &text), file, "cannot read attribute " + name);
        std::string value = text != nullptr ? text : "";
        H5free_memory(text);
        return value;
    }
    std::string value(H5Tget_size(type.get()), '\0');
    Handle memory = string_type(value.size());
    check(H5Aread(attr.get(), memory.get(), value.data()), file, "cannot read attribute " + name);
    value.resize(std::strlen(value.c_str()));
    return value;
}

void write_dataset(const File& file, hid_t parent, const std::string& name,
                   const std::vector<double>& data, const std::vector<hsize_t>& dims,
                   const std::string& unit) {
    write_fixed(file, parent, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, data, dims, unit);
}

void write_dataset(const File& file, hid_t parent, const std::string& name,
                   const std::vector<std::int32_t>& data, const std::vector<hsize_t>& dims,
                   const std::string& unit) {
    write_fixed(file, parent, name, H5T_STD_I32LE, H5T_NATIVE_INT32, data, dims, unit);
}

void write_compressed_dataset(const File& file, hid_t parent, const std::string& name,
                              const std::vector<float>& data, const std::vector<hsize_t>& dims,
                              const std::string& unit) {
    Handle space = dataspace(dims);
    Handle props(H5Pcreate(H5P_DATASET_CREATE));
    // One chunk per leading index (a map per frame), which is how readers slice a time series
    // of maps; deflate (zlib, in every HDF5 build) shrinks the empty cells' NaNs to nothing.
    std::vector<hsize_t> chunk = dims;
    if (!chunk.empty()) chunk[0] = 1;
    for (hsize_t& c : chunk)
        c = std::max<hsize_t>(c, 1);
    const bool chunked = !data.empty();
    if (chunked) {
        H5Pset_chunk(props.get(), static_cast<int>(chunk.size()), chunk.data());
        H5Pset_shuffle(props.get());
        H5Pset_deflate(props.get(), 4);
        H5Pset_fletcher32(props.get());
    }
    Handle set(check(H5Dcreate2(parent, name.c_str(), H5T_IEEE_F32LE, space.get(), H5P_DEFAULT,
                                chunked ? props.get() : H5P_DEFAULT, H5P_DEFAULT),
                     file, "cannot create dataset " + name));
    if (chunked)
        check(H5Dwrite(set.get(), H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()),
              file, "cannot write dataset " + name);
    write_unit(file, set.get(), unit);
}

void write_dataset(const File& file, hid_t parent, const std::string& name,
                   const std::vector<std::uint64_t>& data, const std::vector<hsize_t>& dims) {
    write_fixed(file, parent, name, H5T_STD_U64LE, H5T_NATIVE_UINT64, data, dims, "");
}

void write_string_dataset(const File& file, hid_t parent, const std::string& name,
                          const std::string& text) {
    Handle type = string_type(text.size());
    Handle space(H5Screate(H5S_SCALAR));
    Handle set(check(H5Dcreate2(parent, name.c_str(), type.get(), space.get(), H5P_DEFAULT,
                                H5P_DEFAULT, H5P_DEFAULT),
                     file, "cannot create dataset " + name));
    check(H5Dwrite(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, text.data()), file,
          "cannot write dataset " + name);
}

void replace_string_dataset(const File& file, hid_t parent, const std::string& name,
                            const std::string& text) {
    check(H5Ldelete(parent, name.c_str(), H5P_DEFAULT), file, "cannot replace dataset " + name);
    write_string_dataset(file, parent, name, text);
}

std::vector<double> read_doubles(const File& file, hid_t parent, const std::string& name) {
    return read_all<double>(file, parent, name, H5T_NATIVE_DOUBLE);
}

std::vector<std::int32_t> read_ints(const File& file, hid_t parent, const std::string& name) {
    return read_all<std::int32_t>(file, parent, name, H5T_NATIVE_INT32);
}

std::vector<std::uint64_t> read_uint64s(const File& file, hid_t parent, const std::string& name) {
    return read_all<std::uint64_t>(file, parent, name, H5T_NATIVE_UINT64);
}

std::string read_string_dataset(const File& file, hid_t parent, const std::string& name) {
    Handle set(check(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), file, "no dataset " + name));
    Handle type(H5Dget_type(set.get()));
    if (H5Tget_class(type.get()) != H5T_STRING || H5Tis_variable_str(type.get()) > 0)
        throw FileError(file.path().string(), "dataset " + name + " is not a fixed string");
    std::string text(H5Tget_size(type.get()), '\0');
    Handle memory = string_type(text.size());
    check(H5Dread(set.get(), memory.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, text.data()), file,
          "cannot read dataset " + name);
    text.resize(std::strlen(text.c_str()));
    return text;
}

GrowingDataset GrowingDataset::create(const File& file, hid_t parent, const std::string& name,
                                      hid_t type, const std::vector<hsize_t>& frame_dims,
                                      const std::string& unit) {
    std::vector<hsize_t> dims{0}, max{H5S_UNLIMITED}, chunk{1};
    for (hsize_t d : frame_dims) {
        dims.push_back(d);
        max.push_back(d);
        chunk.push_back(d == 0 ? 1 : d);
    }
    // Scalar series (one number per frame) would make one tiny chunk per frame: chunk them in
    // blocks instead. Per-body arrays get one chunk per frame, which is what readers slice.
    if (frame_dims.empty()) chunk[0] = 64;
    Handle space = dataspace(dims, &max);
    Handle props(H5Pcreate(H5P_DATASET_CREATE));
    H5Pset_chunk(props.get(), static_cast<int>(chunk.size()), chunk.data());
    // A checksum per chunk (a standard filter every HDF5 reader has): a flipped byte in a frame
    // fails its read ("data error detected by fletcher32 checksum") instead of passing as a
    // plausible number. Cost: 4 bytes per chunk and a pass over each chunk (measured in
    // docs/running.md).
    H5Pset_fletcher32(props.get());
    GrowingDataset g;
    g.dataset_ = Handle(check(
        H5Dcreate2(parent, name.c_str(), type, space.get(), H5P_DEFAULT, props.get(), H5P_DEFAULT),
        file, "cannot create dataset " + name));
    write_unit(file, g.dataset_.get(), unit);
    g.frame_dims_ = frame_dims;
    g.name_ = name;
    return g;
}

GrowingDataset GrowingDataset::open(const File& file, hid_t parent, const std::string& name) {
    GrowingDataset g;
    g.dataset_ = Handle(check(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), file,
                              "no dataset " + name + " (not a rodsea trajectory?)"));
    Handle space(H5Dget_space(g.dataset_.get()));
    std::vector<hsize_t> dims(static_cast<size_t>(H5Sget_simple_extent_ndims(space.get())));
    H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
    g.frames_ = dims.at(0);
    g.frame_dims_.assign(dims.begin() + 1, dims.end());
    g.name_ = name;
    return g;
}

void GrowingDataset::append(const File& file, const void* frame, hid_t memory_type) {
    std::vector<hsize_t> size{frames_ + 1}, start{frames_}, count{1};
    for (hsize_t d : frame_dims_) {
        size.push_back(d);
        start.push_back(0);
        count.push_back(d);
    }
    check(H5Dset_extent(dataset_.get(), size.data()), file, "cannot extend " + name_);
    Handle space(H5Dget_space(dataset_.get()));
    check(H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, start.data(), nullptr, count.data(),
                              nullptr),
          file, "cannot select a frame of " + name_);
    Handle memory = dataspace(std::vector<hsize_t>(count.begin(), count.end()));
    check(H5Dwrite(dataset_.get(), memory_type, memory.get(), space.get(), H5P_DEFAULT, frame),
          file, "cannot write a frame of " + name_);
    ++frames_;
}

void GrowingDataset::truncate(const File& file, hsize_t frames) {
    if (frames >= frames_) return;
    std::vector<hsize_t> size{frames};
    size.insert(size.end(), frame_dims_.begin(), frame_dims_.end());
    check(H5Dset_extent(dataset_.get(), size.data()), file, "cannot truncate " + name_);
    frames_ = frames;
}

}  // namespace rodsea::h5
