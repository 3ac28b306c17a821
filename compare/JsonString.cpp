// See JsonString.h.
#include "compare/JsonString.h"

#include <nlohmann/json.hpp>

namespace geocomp::compare {

std::string json_string(const std::string &s)
{
  return nlohmann::json(s).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

} // namespace geocomp::compare
