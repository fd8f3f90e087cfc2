#include "contact/PenetrationChecks.hpp"

#include <sstream>

namespace efg::contact {

std::string tunnelling_message(const std::string& body, const std::string& part, double travel,
                               double spacing) {
  std::ostringstream o;
  o << "rigid body '" << body << "' moved " << travel << " per step against part '" << part
    << "', more than " << kTunnellingFraction << " x its particle spacing " << spacing
    << ", close to its surface: a penalty contact cannot hold it (the body would pass through "
       "the particles within a step); lower dt or dt_scale, or slow the body";
  return o.str();
}

std::string initial_penetration_message(const std::string& contact, long index,
                                        const std::string& body, long long count,
                                        long long particle, const double* X, int dim, double depth,
                                        double spacing) {
  std::ostringstream o;
  o << "contact '" << contact << "' (contacts[" << index << "]): " << count
    << (count == 1 ? " particle starts" : " particles start") << " inside rigid body '" << body
    << "'; the deepest is particle " << particle + 1 << " (X = (";
  for (int k = 0; k < dim; ++k) o << (k ? ", " : "") << X[k];
  o << ")), " << depth << " deep (" << 100.0 * depth / spacing << " % of its spacing " << spacing
    << "); move the body or the part apart, or set contacts[" << index
    << "].initial_penetration: ignore (the initial depth is then not pushed out)";
  return o.str();
}

std::string penetration_warning(const std::string& contact, const std::string& body,
                                double fraction, double threshold, double time) {
  std::ostringstream o;
  o << "contact '" << contact << "': a particle is " << 100.0 * fraction
    << " % of its spacing deep in rigid body '" << body << "' at t = " << time << " (above "
    << "penetration_warning " << threshold
    << "); raise penalty_scale for a stiffer contact (the stable step falls with it)";
  return o.str();
}

}  // namespace efg::contact
