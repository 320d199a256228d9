#include <deal.II/base/exceptions.h>

#include <dyncontact/base/statistics.h>

#include <algorithm>
#include <cmath>
#include <iomanip>

namespace dyncontact
{
  unsigned int
  Statistics::column_index(const std::string &name) const
  {
    const auto it = std::find(columns.begin(), columns.end(), name);
    AssertThrow(it != columns.end(),
                dealii::ExcMessage("statistics has no column '" + name + "'"));
    return it - columns.begin();
  }

  bool
  Statistics::has_column(const std::string &name) const
  {
    return std::find(columns.begin(), columns.end(), name) != columns.end();
  }

  std::vector<double>
  Statistics::column(const std::string &name) const
  {
    const unsigned int  c = column_index(name);
    std::vector<double> values;
    values.reserve(rows.size());
    for (const auto &row : rows)
      values.push_back(row[c]);
    return values;
  }

  void
  Statistics::write_header(std::ostream &out) const
  {
    for (unsigned int c = 0; c < columns.size(); ++c)
      out << (c == 0 ? "" : "\t") << columns[c];
    out << '\n';
  }

  void
  Statistics::write_row(std::ostream &out, const std::vector<double> &row) const
  {
    out << std::setprecision(12);
    for (unsigned int c = 0; c < row.size(); ++c)
      out << (c == 0 ? "" : "\t") << row[c];
    out << '\n';
  }

  unsigned int
  Statistics::row_of_largest(const std::string &name) const
  {
    const std::vector<double> v    = column(name);
    unsigned int              best = 0;
    for (unsigned int r = 0; r < v.size(); ++r)
      if (!std::isnan(v[r]) && (std::isnan(v[best]) || v[r] > v[best]))
        best = r;
    return best;
  }

  unsigned int
  Statistics::row_of_last_value(const std::string &name) const
  {
    const std::vector<double> v = column(name);
    for (unsigned int r = v.size(); r > 0; --r)
      if (!std::isnan(v[r - 1]))
        return r - 1;
    return v.size() - 1;
  }

  double
  Statistics::sum(const std::string &name) const
  {
    double sum = 0.;
    if (has_column(name))
      for (const double v : column(name))
        sum += v;
    return sum;
  }
} // namespace dyncontact
