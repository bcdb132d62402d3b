// The series argument of `pattern Plain tag SERIES` and `pattern UniformExcitation .. -accel SERIES`:
// a timeSeries tag, or (as OpenSees' TclSeriesCommand) an inline definition such as {Path -dt 0.01 -filePath
// v.txt -factor 2.5} or {Linear}, whose tag is optional.
#include <tcl.h>

#include "fem_tcl/tcl/commands.hpp"

namespace fem::tcl {

std::shared_ptr<domain::TimeSeries> series_argument(Context& ctx, common::CommandArgs& args, const std::string& word) {
  if (const auto tag = common::CommandArgs::parse_integer(word)) {
    const auto it = ctx.time_series.find(*tag);
    if (it == ctx.time_series.end()) args.fail("timeSeries " + std::to_string(*tag) + " does not exist");
    return it->second;
  }
  int count = 0;
  const char** parts = nullptr;
  if (!ctx.interp || Tcl_SplitList(ctx.interp, word.c_str(), &count, &parts) != TCL_OK || count == 0) {
    if (parts) Tcl_Free(reinterpret_cast<char*>(parts));
    args.fail("expected a timeSeries tag or an inline series {type <tag> options..}, got '" + word + "'");
  }
  std::vector<std::string> words(parts, parts + count);
  Tcl_Free(reinterpret_cast<char*>(parts));
  // the inline tag is optional: insert 0 when the word after the type is not an integer
  if (words.size() < 2 || !common::CommandArgs::parse_integer(words[1])) words.insert(words.begin() + 1, "0");
  common::CommandArgs sub(args.command() + " series {" + word + "}",
                          "timeSeries type <tag> options.. (see the timeSeries command)", words);
  return domain::parse_time_series(sub);
}

}  // namespace fem::tcl
