#include "config/reference_table.hpp"

#include "config/input_error.hpp"
#include "config/text_lines.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

namespace geartrib::io {

ReferenceTable read_reference_table(const std::filesystem::path& file,
                                    const std::function<Dimension(const std::string&)>& dimension_of) {
  ReferenceTable t;
  t.file = file.string();
  std::istringstream in(read_data_file(file, kMaxTableFileBytes));  // a regular file of at most 64 MiB
  std::vector<double> factors;
  std::string line;
  int n = 0;
  bool header_seen = false;
  while (std::getline(in, line)) {
    ++n;
    const std::string s = trim(line);
    if (s.empty()) continue;
    if (s.front() == '#') {
      if (auto entry = comment_entry(s)) t.provenance.push_back(std::move(*entry));
      continue;
    }
    const auto cells = split_csv(s);
    if (!header_seen) {
      header_seen = true;
      if (cells.size() < 2)
        throw InputError(t.file, n, "", s, "header needs an input column and at least one quantity");
      t.input_name = cells[0];
      for (std::size_t i = 1; i < cells.size(); ++i) {
        const std::string& h = cells[i];
        const auto at = h.find('@');
        const auto lb = h.find('[');
        const auto rb = h.find(']');
        if (lb == std::string::npos || rb == std::string::npos || rb < lb || rb + 1 != h.size())
          throw InputError(t.file, n, h, "", "column name must be quantity@label[unit]");
        ReferenceColumn c;
        c.quantity = h.substr(0, std::min(at, lb));
        c.label = at != std::string::npos && at < lb ? h.substr(at + 1, lb - at - 1) : "";
        c.unit = h.substr(lb + 1, rb - lb - 1);
        try {
          const Dimension d = dimension_of(c.quantity);
          factors.push_back(d == Dimension::dimensionless && c.unit.empty() ? 1.0 : unit_factor(c.unit, d));
        } catch (const std::invalid_argument& e) {
          throw InputError(t.file, n, h, "", e.what());
        }
        t.columns.push_back(std::move(c));
      }
      continue;
    }
    if (cells.size() != t.columns.size() + 1)
      throw InputError(
          t.file, n, "", s,
          "row has " + std::to_string(cells.size()) + " cells, header has " + std::to_string(t.columns.size() + 1));
    for (std::size_t i = 0; i < cells.size(); ++i) {
      double v = 0.0;
      const auto [end, ec] = std::from_chars(cells[i].data(), cells[i].data() + cells[i].size(), v);
      if (ec != std::errc{} || end != cells[i].data() + cells[i].size() || !std::isfinite(v))
        throw InputError(t.file, n, i == 0 ? t.input_name : t.columns[i - 1].quantity, cells[i], "not a finite number");
      if (i == 0) {
        t.inputs.push_back(v);
      } else {
        const double si = v * factors[i - 1];  // finite in the file's unit, and in SI
        if (!std::isfinite(si))
          throw InputError(t.file, n, t.columns[i - 1].quantity, cells[i], "not finite in SI units (it overflows)");
        t.columns[i - 1].values.push_back(si);
      }
    }
  }
  if (t.inputs.empty()) throw InputError(t.file, n, "", "", "reference table has no data rows");
  return t;
}

}  // namespace geartrib::io
