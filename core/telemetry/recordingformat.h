// Facts of the recording format shared by its writer (recordingwriter.cpp) and its reader
// (recordingreader.cpp); docs/recording.md describes them for people.
#pragma once

#include <QtGlobal>

namespace hatpic::recording {

inline constexpr char kFormatTag[] = "hatpic-recording";
inline constexpr int kFormatVersion = 1;
inline constexpr qsizetype kMaxLineBytes = 8192;              //!< longest CSV line a reader accepts
inline constexpr qint64 kMaxMetadataBytes = 16 * 1024 * 1024; //!< largest .json a reader reads
//! What a reader holds of one recording, at most (a replay): samples (16.7 min at 1 kHz; about
//! 136 MB in the replay's buffer, 136 bytes a sample) and events (1000 s at the writer's 50
//! events/s), with at most kMaxReadEventChars of event text in all. A reader stops at the first
//! bound it meets and says so; the rest of the file is not read.
inline constexpr qint64 kMaxReadSamples = 1'000'000;
inline constexpr qint64 kMaxReadEvents = 50'000;
inline constexpr qint64 kMaxReadEventChars = 4 * 1024 * 1024;

} // namespace hatpic::recording
