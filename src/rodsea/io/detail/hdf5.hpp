#pragma once
// A thin RAII layer over the HDF5 C API, private to src/rodsea/io: every failure becomes a
// FileError naming the file and the object, so no caller checks a return code or leaks an id.
#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace rodsea::h5 {

// Owns one HDF5 id and closes it with the matching H5?close.
class Handle {
  public:
    Handle() = default;
    explicit Handle(hid_t id) : id_(id) {}
    Handle(Handle&& other) noexcept : id_(other.id_) { other.id_ = H5I_INVALID_HID; }
    Handle& operator=(Handle&& other) noexcept;
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    ~Handle() { reset(); }

    hid_t get() const { return id_; }
    void reset();
    // Forgets the id without closing it: for objects of a file whose writes failed, which HDF5
    // 1.10 may crash closing. The process is about to stop; the OS reclaims them.
    void release() { id_ = H5I_INVALID_HID; }

  private:
    hid_t id_ = H5I_INVALID_HID;
};

// The file an operation failed in, for messages: set by File, read by every helper.
class File {
  public:
    static File create(const std::filesystem::path& path);  // truncates an existing file
    static File open(const std::filesystem::path& path, bool writable);

    hid_t id() const { return handle_.get(); }
    const std::filesystem::path& path() const { return path_; }
    void flush() const;
    void close();  // throws when the final write fails (a full disk shows up here)
    void abandon() { handle_.release(); }  // see Handle::release

  private:
    File(Handle handle, std::filesystem::path path)
        : handle_(std::move(handle)), path_(std::move(path)) {}
    Handle handle_;
    std::filesystem::path path_;
};

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& what);

Handle create_group(const File& file, hid_t parent, const std::string& name);
Handle open_group(const File& file, hid_t parent, const std::string& name);
Handle open_dataset(const File& file, hid_t parent, const std::string& name);
bool exists(hid_t parent, const std::string& path);

void write_attribute(const File& file, hid_t object, const std::string& name,
                     const std::string& value);
void write_attribute(const File& file, hid_t object, const std::string& name,
                     const std::vector<std::string>& values);
void write_attribute(const File& file, hid_t object, const std::string& name,
                     const std::vector<std::string>& values, bool scalar);
void write_attribute(const File& file, hid_t object, const std::string& name,
                     const std::vector<std::int32_t>& values);
void write_attribute(const File& file, hid_t object, const std::string& name, double value);
void write_attribute(const File& file, hid_t object, const std::string& name, std::int32_t value);
void write_attribute(const File& file, hid_t object, const std::string& name, std::int64_t value);
std::string read_string_attribute(const File& file, hid_t object, const std::string& name);
// A scalar integer attribute of any integer type that fits; FileError otherwise.
std::int64_t read_int64_attribute(const File& file, hid_t object, const std::string& name);

// Fixed-size datasets, written once. `dims` multiply to data.size().
void write_dataset(const File& file, hid_t parent, const std::string& name,
                   const std::vector<double>& data, const std::vector<hsize_t>& dims,
                   const std::string& unit = "");
void write_dataset(const File& file, hid_t parent, const std::string& name,
                   const std::vector<std::int32_t>& data, const std::vector<hsize_t>& dims,
                   const std::string& unit = "");
void write_dataset(const File& file, hid_t parent, const std::string& name,
                   const std::vector<std::uint64_t>& data, const std::vector<hsize_t>& dims);
// Single precision, chunked by the first dimension, shuffled and deflated, with checksums: for
// large arrays of measured values (time series of maps), where 7 digits are more than they hold.
void write_compressed_dataset(const File& file, hid_t parent, const std::string& name,
                              const std::vector<float>& data, const std::vector<hsize_t>& dims,
                              const std::string& unit = "");
void write_string_dataset(const File& file, hid_t parent, const std::string& name,
                          const std::string& text);
// Deletes the dataset `name` (a fixed string of another length cannot be overwritten in place) and
// writes `text` in its place.
void replace_string_dataset(const File& file, hid_t parent, const std::string& name,
                            const std::string& text);

// Whole-dataset reads, flattened.
std::vector<double> read_doubles(const File& file, hid_t parent, const std::string& name);
std::vector<std::int32_t> read_ints(const File& file, hid_t parent, const std::string& name);
std::vector<std::uint64_t> read_uint64s(const File& file, hid_t parent, const std::string& name);
std::string read_string_dataset(const File& file, hid_t parent, const std::string& name);

// A dataset that grows along its first axis, one frame (a block of `frame_dims`) at a time:
// the H5MD "value", "step" and "time" arrays.
class GrowingDataset {
  public:
    GrowingDataset() = default;
    static GrowingDataset create(const File& file, hid_t parent, const std::string& name,
                                 hid_t type, const std::vector<hsize_t>& frame_dims,
                                 const std::string& unit = "");
    static GrowingDataset open(const File& file, hid_t parent, const std::string& name);

    hsize_t frames() const { return frames_; }
    void append(const File& file, const void* frame, hid_t memory_type);
    void truncate(const File& file, hsize_t frames);  // drops frames beyond `frames`
    void abandon() { dataset_.release(); }

  private:
    Handle dataset_;
    std::vector<hsize_t> frame_dims_;
    hsize_t frames_ = 0;
    std::string name_;
};

}  // namespace rodsea::h5
