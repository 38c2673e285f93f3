#include "fem/deck_format.hpp"

#include <fmt/format.h>

namespace geartrib::fem {

std::vector<double> graded_grid(double first, double h0, double fine, double total, double growth) {
  std::vector<double> x{0.0};
  if (first > 0.0) x.push_back(first);
  while (x.back() + 0.5 * h0 < fine) x.push_back(x.back() + h0);
  double h = h0;
  while (x.back() < total) {
    h *= growth;
    x.push_back(x.back() + h);
  }
  return x;
}

std::string deck_number(double v) { return fmt::format("{:.12e}", v); }

void write_id_lines(std::string& out, const std::vector<int>& ids) {
  for (std::size_t k = 0; k < ids.size(); ++k) out += fmt::format("{}{}", ids[k], (k + 1) % 10 == 0 || k + 1 == ids.size() ? "\n" : ", ");
}

}  // namespace geartrib::fem
