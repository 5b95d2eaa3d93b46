// The subcommands of rayconv, one function each; rayconv.cpp wires them to the command line.
#pragma once

#include "converters/rays/ray_stream.h"

#include <CLI/CLI.hpp>
#include <string>

namespace rayset::rayconv {

// Options every subcommand that reads rays shares.
struct ReadFlags {
    std::string from;   // format name, empty = detect
    std::string trust;  // "", "header", "rays"
    bool normalise = false;
    RayReadOptions options() const;
};
void add_read_flags(CLI::App& command, ReadFlags& flags);

// True for .ies/.ldt names and for files whose content is IES or EULUMDAT.
bool is_photometry(const std::string& path);

// Opens rays and prints the reader's warnings when it is done (see finish_reading).
std::unique_ptr<RayReader> open_input(const std::string& path, const ReadFlags& flags);
void print_warnings(const RayReader& reader);

// The output format: --to if given, else from the extension, else an error that says what to do.
RayFormat output_format(const std::string& path, const std::string& to);

void register_info(CLI::App& app);
void register_convert(CLI::App& app);
void register_make(CLI::App& app);  // synth, emit, farfield
void register_ops(CLI::App& app);   // subsample, merge, transform

}  // namespace rayset::rayconv
