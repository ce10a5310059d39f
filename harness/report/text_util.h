// Small text helpers shared by the report writers (HTML, SVG, JUnit): escaping, fixed number
// formatting and atomic file writes. Everything here is locale-independent so two runs over the
// same results produce byte-identical files.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "core/output_file.h"

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

// Reports are written with taa::writeFileAtomically (core/output_file.h): readers never see
// a half-written file, and a failure is an OutputError naming it.
using taa::writeFileAtomically;

}  // namespace taa::report
