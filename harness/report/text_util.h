// Small text helpers shared by the report writers (HTML, SVG, JUnit): escaping, fixed number
// formatting and atomic file writes. Everything here is locale-independent so two runs over the
// same results produce byte-identical files.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace taa::report {

// Escapes &, <, >, " and ' for element text and attribute values alike (HTML and XML). Control
// characters other than tab, LF and CR are not allowed in XML 1.0, so they become U+FFFD.
std::string escapeMarkup(std::string_view text);

// Percent-encodes a relative path for use in a src/href attribute: everything but unreserved
// characters and '/' is encoded, so '#', '?', '%' and spaces in file names cannot change what
// the browser loads.
std::string encodePath(std::string_view relativePath);

// `significant` significant digits in the shortest of fixed/scientific notation (like %g, but
// independent of the C locale); non-finite values print as "inf", "-inf" and "nan".
std::string formatNumber(double value, int significant = 4);

// Exactly `decimals` digits after the point; non-finite values as in formatNumber.
std::string formatFixed(double value, int decimals);

// Writes `content` to a hidden temporary file beside `file`, flushes it and renames it over
// `file`, so readers never see a half-written report. Throws std::runtime_error on failure and
// leaves an existing `file` untouched.
void writeFileAtomically(const std::filesystem::path& file, std::string_view content);

}  // namespace taa::report
