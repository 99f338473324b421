// error.cpp: message helpers shared by every error path.
#include "error.h"

#include <OpenImageIO/strutil.h>

namespace mcdtool {

std::string one_line(std::string message)
{
    message = OIIO::Strutil::strip(message);
    std::string out;
    for (char ch : message) {
        if (ch == '\n' || ch == '\r') {
            if (!out.empty() && out.back() != ' ')
                out += "; ";
            continue;
        }
        out += ch;
    }
    return out;
}

}  // namespace mcdtool
