// Amplitude spectrum of a uniformly sampled signal: Hann window, FFT (FFTW3), dB
// (docs/experiments.md § Spectrum).
//
// Plain C++20: no Qt.
#pragma once

#include <span>
#include <vector>

namespace hatpic::analysis {

struct Spectrum
{
    std::vector<double> frequency;   //!< bin centres, 0 … rate/2 [Hz]
    std::vector<double> amplitude;   //!< amplitude of a sine at the bin [signal unit]
    std::vector<double> magnitudeDb; //!< 20·log10(amplitude), floored at kFloorDb [dB]
    double resolution = 0;           //!< bin spacing rate/N [Hz]

    static constexpr double kFloorDb = -300; //!< what an exact zero reads [dB]
};

//! The one-sided amplitude spectrum of `x` sampled at `rate` [Hz]: the mean taken out, a
//! periodic Hann window, a real FFT, scaled by the window's coherent gain (½) so a sine of
//! amplitude A centred on a bin reads A (20·log10 A dB). Empty for fewer than 2 samples or a
//! rate that is not positive.
Spectrum amplitudeSpectrum(std::span<const double> x, double rate);

//! The sampling rate of times t: 1 / the median spacing [Hz]; 0 for fewer than 2 samples.
double sampleRate(std::span<const double> t);

struct SpectrumPeak
{
    double frequency = 0;   //!< [Hz]
    double amplitude = 0;   //!< [signal unit]
    double magnitudeDb = 0; //!< [dB]
};

//! The largest bin at or above `minFrequency` [Hz]; frequency NaN when there is none.
SpectrumPeak dominantPeak(const Spectrum &spectrum, double minFrequency = 0);

} // namespace hatpic::analysis
