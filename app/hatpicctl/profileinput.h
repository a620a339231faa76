// Reading the profile a subcommand was given, with errors and warnings on stderr.
#pragma once

#include "profile/profile.h"

#include <QString>

#include <optional>

namespace hatpic::cli {

//! Reads `path`. Warnings are printed as "warning: …"; a refused file prints one sentence
//! followed by every error (indented) and gives nullopt.
std::optional<Profile> loadProfile(const QString &path);

} // namespace hatpic::cli
