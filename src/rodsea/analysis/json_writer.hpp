#pragma once
// A small streaming JSON writer: enough for analysis.json without a dependency. Non-finite
// numbers become null (JSON has no NaN), numbers keep 17 significant digits.
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace rodsea {

class JsonWriter {
  public:
    JsonWriter& begin_object(std::string_view key = {});
    JsonWriter& end_object();
    JsonWriter& begin_array(std::string_view key = {});
    JsonWriter& end_array();
    JsonWriter& value(std::string_view key, double v);
    JsonWriter& value(std::string_view key, long long v);
    JsonWriter& value(std::string_view key, bool v);
    JsonWriter& value(std::string_view key, std::string_view v);
    JsonWriter& value(std::string_view key, const char* v) {
        return value(key, std::string_view(v));
    }
    JsonWriter& element(double v) { return value({}, v); }
    JsonWriter& element(std::string_view v) { return value({}, v); }
    std::string str() const { return out_.str() + "\n"; }

    static std::string quote(std::string_view s);
    static std::string number(double v);

  private:
    void prefix(std::string_view key);
    std::ostringstream out_;
    std::vector<bool> first_;  // per open container: nothing written in it yet
};

}  // namespace rodsea
