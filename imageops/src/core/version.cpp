// version.cpp: the loaded library's version (mcdenoise/version.h).
#include <mcdenoise/version.h>

namespace mcdenoise {

const char* version() { return MCDENOISE_VERSION_STRING; }

int version_number() { return MCDENOISE_VERSION; }

}  // namespace mcdenoise
