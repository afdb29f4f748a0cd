// Drawing a Figure (chart.h) with PLplot's cairo drivers (pngcairo, svgcairo; Debian
// plplot-driver-cairo), into memory: the report writes the files (docs/report.md).
#pragma once

#include <string>

#include "uuvplan/report/chart.h"

namespace uuvplan::report {

enum class Format { kPng, kSvg };

/// The figure as a PNG or SVG file's bytes. Throws std::runtime_error when the driver is
/// missing or the drawing fails.
std::string Render(const Figure& figure, Format format);

}  // namespace uuvplan::report
