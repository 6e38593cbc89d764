#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "volmesh/fem/study.hpp"

namespace volmesh::fem {

namespace {

// %.10g keeps the CSV exact enough to recompute rates and identical from run to run.
std::string number(double v) {
  if (!std::isfinite(v)) return "";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", v);
  return buffer;
}

std::string fixed(const char* format, double v, int width) {
  char buffer[48];
  if (std::isfinite(v))
    std::snprintf(buffer, sizeof buffer, format, v);
  else
    std::snprintf(buffer, sizeof buffer, "%s", "-");
  std::string s = buffer;
  return std::string(std::max(0, width - static_cast<int>(s.size())), ' ') + s;
}

// RFC 4180 quoting for a label that needs it.
std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

}  // namespace

std::string convergence_csv(std::span<const ConvergenceSeries> series) {
  std::ostringstream csv;
  csv << "series,level,h,cells,dofs,l2,linf,h1,rate_l2,rate_linf,rate_h1\n";
  for (const ConvergenceSeries& s : series) {
    const SeriesRates rates = convergence_rates(s);
    for (std::size_t i = 0; i < s.levels.size(); ++i) {
      const LevelResult& r = s.levels[i];
      csv << csv_field(s.label) << ',' << r.level << ',' << number(r.h) << ',' << r.cells << ',' << r.dofs;
      for (Norm n : kNorms) csv << ',' << number(norm_value(r.errors, n));
      for (std::size_t k = 0; k < kNorms.size(); ++k)
        csv << ',' << (i == 0 ? "" : number(rates.pairwise[k][i - 1]));
      csv << '\n';
    }
  }
  return csv.str();
}

void print_convergence_table(std::ostream& out, std::span<const ConvergenceSeries> series) {
  for (const ConvergenceSeries& s : series) {
    const SeriesRates rates = convergence_rates(s);
    out << s.label << "\n"
        << "level         h     cells      DOFs        L2  rate      Linf  rate        H1  rate\n";
    for (std::size_t i = 0; i < s.levels.size(); ++i) {
      const LevelResult& r = s.levels[i];
      out << fixed("%.0f", r.level, 5) << fixed("%.4g", r.h, 10) << fixed("%.0f", r.cells, 10)
          << fixed("%.0f", r.dofs, 10);
      for (std::size_t k = 0; k < kNorms.size(); ++k)
        out << fixed("%.3e", norm_value(r.errors, kNorms[k]), 10)
            << (i == 0 ? std::string(6, ' ') : fixed("%.2f", rates.pairwise[k][i - 1], 6));
      out << "\n";
    }
    out << "least-squares slope:";
    for (std::size_t k = 0; k < kNorms.size(); ++k)
      out << "  " << norm_name(kNorms[k]) << fixed("%.2f", rates.slope[k], 6);
    out << "\n";
  }
}

}  // namespace volmesh::fem
