#pragma once

#include <string>

namespace shelfdock::io {

/// Walks the record structure of a ROS 1 bag (format 2.0) before librosbag reads it, and throws
/// InputError naming the file and the byte offset when a length or position in it could not be
/// right: a record longer than what is left of the file, an index or chunk position that is not
/// the start of a record, a chunk whose stated size is over kMaxBagChunkBytes or differs from
/// its data. librosbag trusts these fields and allocates what they say (a truncated or corrupt
/// bag would otherwise cost gigabytes or crash); only record headers are read here.
void PrecheckBag(const std::string& path);

}  // namespace shelfdock::io
