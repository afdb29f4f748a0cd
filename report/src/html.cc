#include "uuvplan/report/html.h"

#include <cctype>
#include <sstream>

namespace uuvplan::report {

namespace {

// Readable at 1366×768 and printable: one column at most 1180 px wide, tables that scroll
// sideways inside their box rather than widening the page, figures scaled to the column.
constexpr const char* kStyle = R"(
body{font-family:"DejaVu Sans",Helvetica,Arial,sans-serif;margin:0;color:#222;background:#fff}
main{max-width:1180px;margin:0 auto;padding:12px 24px 48px}
header{border-bottom:2px solid #0072b2;margin-bottom:8px}
h1{font-size:1.6em;margin:8px 0 2px}h2{font-size:1.25em;margin:28px 0 8px;color:#0072b2}
.sub{color:#555;margin:0 0 8px}nav{font-size:.95em;margin:6px 0 12px}
nav a{margin-right:14px;color:#0072b2;text-decoration:none}
.table{overflow-x:auto;margin:8px 0 14px}
table{border-collapse:collapse;font-size:.9em}caption{text-align:left;font-weight:bold;padding:4px 0}
th,td{border:1px solid #ccc;padding:3px 8px;text-align:right;white-space:nowrap}
th{background:#eef4fa;text-align:left}td.t{text-align:left}
figure{margin:12px 0 20px}figure img{width:100%;height:auto;border:1px solid #ddd}
figcaption{font-size:.9em;color:#444;margin-top:4px}
)";

std::string Escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// Numbers align right, words left: a cell is a number when it starts like one.
bool IsNumber(const std::string& cell) {
  const std::size_t i = !cell.empty() && (cell[0] == '-' || cell[0] == '+') ? 1 : 0;
  return cell == "—" || (i < cell.size() && std::isdigit(static_cast<unsigned char>(cell[i])));
}

void WriteTable(const Table& t, std::ostream& out) {
  out << "<div class=\"table\"><table>";
  if (!t.caption.empty()) out << "<caption>" << Escape(t.caption) << "</caption>";
  out << "<thead><tr>";
  for (const auto& h : t.header) out << "<th>" << Escape(h) << "</th>";
  out << "</tr></thead><tbody>\n";
  for (const auto& row : t.rows) {
    out << "<tr>";
    for (const auto& cell : row)
      out << (IsNumber(cell) ? "<td>" : "<td class=\"t\">") << Escape(cell) << "</td>";
    out << "</tr>\n";
  }
  out << "</tbody></table></div>\n";
}

void WriteSection(const Section& s, std::ostream& out) {
  out << "<section id=\"" << Escape(s.id) << "\"><h2>" << Escape(s.title) << "</h2>\n";
  for (const auto& p : s.paragraphs) out << "<p>" << Escape(p) << "</p>\n";
  for (const auto& t : s.tables) WriteTable(t, out);
  for (const auto& f : s.figures) {
    out << "<figure id=\"fig-" << Escape(f.name) << "\"><img alt=\"" << Escape(f.name)
        << "\" src=\"data:image/png;base64," << Base64(f.png) << "\"><figcaption>"
        << Escape(f.caption) << " (files: " << Escape(f.name) << ".png, " << Escape(f.name)
        << ".svg)</figcaption></figure>\n";
  }
  out << "</section>\n";
}

}  // namespace

std::string Base64(const std::string& bytes) {
  static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    unsigned v = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      v = (v << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    }
    for (std::size_t k = 0; k < 4; ++k) {
      out += k <= n ? kAlphabet[(v >> (18 - 6 * k)) & 63] : '=';
    }
  }
  return out;
}

std::string Html(const Document& d) {
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
      << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
      << "<title>" << Escape(d.title) << "</title><style>" << kStyle << "</style></head>\n"
      << "<body><main><header><h1>" << Escape(d.title) << "</h1><p class=\"sub\">"
      << Escape(d.subtitle) << "</p><nav>";
  for (const auto& s : d.sections) {
    out << "<a href=\"#" << Escape(s.id) << "\">" << Escape(s.title) << "</a>";
  }
  out << "</nav></header>\n";
  for (const auto& s : d.sections) WriteSection(s, out);
  out << "</main></body></html>\n";
  return out.str();
}

}  // namespace uuvplan::report
