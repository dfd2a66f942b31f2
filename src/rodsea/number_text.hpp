#pragma once
// Numbers as text in files: the shortest text that reads back as the same double (std::to_chars:
// no locale, exact); "nan", "inf" and "-inf" for the non-finite.
#include <string>

namespace rodsea {

std::string exact_number(double value);

}  // namespace rodsea
