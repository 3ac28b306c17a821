#include "common/Response.h"

namespace geocomp {

int Response::extra_index(const std::string &name) const
{
  for (std::size_t i = 0; i < extras.size(); ++i)
    if (extras[i].name == name)
      return static_cast<int>(i);
  return -1;
}

std::vector<const ResponseSample *> Response::path(int branch) const
{
  std::vector<const ResponseSample *> out;
  for (const auto &s : samples)
    if (s.branch == branch)
      out.push_back(&s);
  return out;
}

Response with_interval_means(Response response)
{
  if (response.interval_means)
    for (ResponseSample &s : response.samples)
      s.stress = s.stress_mean;
  return response;
}

} // namespace geocomp
