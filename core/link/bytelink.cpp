#include "bytelink.h"
#include "linksource.h"

namespace hatpic {

ByteLink::~ByteLink() = default;

LinkSource::~LinkSource() = default;

} // namespace hatpic
