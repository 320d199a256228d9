#ifndef dyncontact_base_statistics_h
#define dyncontact_base_statistics_h

#include <ostream>
#include <string>
#include <vector>

namespace dyncontact
{
  /**
   * The per-step table that is also written to statistics.tsv: a fixed list
   * of columns and one row of numbers per time step.
   */
  struct Statistics
  {
    std::vector<std::string>         columns;
    std::vector<std::vector<double>> rows;

    /// Index of a column; throws if there is none of that name.
    unsigned int
    column_index(const std::string &name) const;

    bool
    has_column(const std::string &name) const;

    /// All values of one column, one per row.
    std::vector<double>
    column(const std::string &name) const;

    void
    write_header(std::ostream &out) const;

    void
    write_row(std::ostream &out, const std::vector<double> &row) const;

    /// The row of the largest value of column @p name (the first one;
    /// rows without a value, nan, are left out).
    unsigned int
    row_of_largest(const std::string &name) const;

    /// The row of the last value of column @p name that is not nan.
    unsigned int
    row_of_last_value(const std::string &name) const;

    /// The sum of the values of column @p name (0 if there is none).
    double
    sum(const std::string &name) const;
  };
} // namespace dyncontact

#endif
