#pragma once
// The one error type for bad input: it always names the parameter, the value given and the
// range that would have been accepted, so that a user can fix the config without reading code.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace rodsea {

class InvalidParameter : public std::invalid_argument {
  public:
    InvalidParameter(const std::string& name, const std::string& value, const std::string& allowed,
                     const std::string& why = "");
    const std::string& name() const { return name_; }
    // The same error, saying where it arose: "... (campaign point phi=0.8)".
    InvalidParameter in_context(const std::string& context) const;

  private:
    struct Message {};
    InvalidParameter(Message, const std::string& name, const std::string& message)
        : std::invalid_argument(message), name_(name) {}
    std::string name_;
};

// A file or directory that cannot be read or written: names the path and what went wrong.
class FileError : public std::runtime_error {
  public:
    FileError(const std::string& path, const std::string& what)
        : std::runtime_error(path + ": " + what), path_(path) {}
    const std::string& path() const { return path_; }

  private:
    std::string path_;
};

std::string format_number(double value);

// Each check throws InvalidParameter naming `name` when the value is outside the range.
// The unit string is appended to numbers in the message ("0.5 mm").
void require_finite(const std::string& name, double value, const std::string& unit = "");
void require_positive(const std::string& name, double value, const std::string& unit = "");
void require_non_negative(const std::string& name, double value, const std::string& unit = "");
void require_in_closed_range(const std::string& name, double value, double lo, double hi,
                             const std::string& unit = "");
void require_positive_count(const std::string& name, long long value);

}  // namespace rodsea
