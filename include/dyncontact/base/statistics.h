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
  };
} // namespace dyncontact

#endif
