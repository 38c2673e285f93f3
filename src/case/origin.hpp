// Where a case value came from, recorded by the loader (io::load_case) for every key it resolves:
// a line of a file, a --set change, or the default. The located errors and warnings of the
// configuration layer (config/case_records.hpp) and the parameters' records (/parameters, `geartrib
// case`, Python's Case.parameters) read it.
#pragma once

#include <string>

namespace geartrib {

struct Origin {
  enum class Kind {
    file,           // a line of the case file, or a data file named whole (line 0: a lubricant file, the FZG table)
    set,            // a --set change (or a sweep point's)
    default_value,  // absent: the option struct's default
  };
  Kind kind = Kind::default_value;
  std::string file;  // the case file (file, set, default) or the data file the value was taken from
  int line = 0;      // 1-based; a default's: its enclosing table's line when the file has the table; 0: none
  int column = 0;    // 1-based; 0: not known
  // A --set change as typed, `--set set_key=set_value`: set_key the key itself or a table it lies in.
  std::string set_key, set_value;

  // A data file (or table) the value was taken from, named whole: a lubricant file, the FZG table.
  static Origin data_file(std::string name) {
    Origin o;
    o.kind = Kind::file;
    o.file = std::move(name);
    return o;
  }

  // As /parameters and `geartrib case` show it: "file:line", "file", "--set" or "default".
  std::string text() const {
    switch (kind) {
      case Kind::set:
        return "--set";
      case Kind::default_value:
        return "default";
      case Kind::file:
        break;
    }
    return line > 0 ? file + ":" + std::to_string(line) : file;
  }
  // Where a message locates it: the file (with "(--set KEY=VALUE)" for a change) and the line (0: none).
  std::string where_file() const {
    return kind == Kind::set ? file + " (--set " + set_key + "=" + set_value + ")" : file;
  }
  int where_line() const { return kind == Kind::set ? 0 : line; }
  // "file:line" or "file (--set KEY=VALUE)": the prefix of a located warning.
  std::string where() const {
    const int l = where_line();
    return l > 0 ? where_file() + ":" + std::to_string(l) : where_file();
  }
};

}  // namespace geartrib
