#include "bytelink.h"

namespace hatpic {

ByteLink::~ByteLink() = default;

} // namespace hatpic
