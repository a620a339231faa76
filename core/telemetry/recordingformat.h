// Facts of the recording format shared by its writer (recordingwriter.cpp) and its reader
// (recordingreader.cpp); docs/recording.md describes them for people.
#pragma once

#include <QtGlobal>

namespace hatpic::recording {

inline constexpr char kFormatTag[] = "hatpic-recording";
inline constexpr int kFormatVersion = 1;
inline constexpr qsizetype kMaxLineBytes = 8192;              //!< longest CSV line a reader accepts
inline constexpr qint64 kMaxMetadataBytes = 16 * 1024 * 1024; //!< largest .json a reader reads

} // namespace hatpic::recording
