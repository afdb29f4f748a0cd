// The report as one self-contained HTML file: sections of paragraphs, tables (every quantity
// column names its unit in its header) and figures embedded as data: URIs (PNG, base64), a
// small inline style sheet, no script and nothing fetched from the network.
#pragma once

#include <string>
#include <vector>

namespace uuvplan::report {

struct Table {
  std::string caption;
  std::vector<std::string> header;  ///< "duration (s)": the unit in the header
  std::vector<std::vector<std::string>> rows;
};

struct EmbeddedFigure {
  std::string name;  ///< file stem (also the figure's files beside the report)
  std::string caption;
  std::string png;  ///< the PNG file's bytes
};

struct Section {
  std::string id;  ///< HTML id, e.g. "vehicle"
  std::string title;
  std::vector<std::string> paragraphs;  ///< plain text (escaped when written)
  std::vector<Table> tables;
  std::vector<EmbeddedFigure> figures;
};

struct Document {
  std::string title;
  std::string subtitle;  ///< what was reported on, e.g. the input file
  std::vector<Section> sections;
};

/// The whole HTML text of `document`.
std::string Html(const Document& document);

/// RFC 4648 base64 of `bytes` (for data: URIs).
std::string Base64(const std::string& bytes);

}  // namespace uuvplan::report
