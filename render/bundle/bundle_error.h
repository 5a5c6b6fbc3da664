#pragma once
// The one exception a bundle that cannot be used raises. what() reads
//   bundle <file>: section 'sdf.d': checksum mismatch (stored 0x..., computed 0x...)
// and section() names the part that failed: a section name, or "" for the header, the
// section table or the file as a whole (then part() says which).
#include <stdexcept>
#include <string>

namespace weft::bundle {

class BundleError : public std::runtime_error {
public:
  // part: "header", "section table", "file", or "section '<name>'"; section: the name or "".
  BundleError(const std::string& origin, std::string part, std::string section,
              const std::string& detail)
      : std::runtime_error("bundle " + origin + ": " + part + ": " + detail),
        part_(std::move(part)), section_(std::move(section)) {}

  const std::string& part() const { return part_; }
  const std::string& section() const { return section_; }

private:
  std::string part_;
  std::string section_;
};

}  // namespace weft::bundle
