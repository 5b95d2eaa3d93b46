// What the harnesses share: the file an input is written to (the readers take paths) and the
// reading of a ray file as the tools read it.
#pragma once

#include "converters/rays/ray.h"
#include "core/error.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace rayset::fuzz {

// A folder of this process's own under /dev/shm (memory, so that the many small writes cost no
// disk), made on the first call; it goes when the process ends.
const std::string& input_folder();

// Writes the bytes libFuzzer hands over to the file `name` in input_folder() and returns its
// path. Each call replaces the previous input of that name.
std::string write_input(const uint8_t* data, size_t size, const std::string& name);

// The errors of a reader name the file they are about (core/error.h: "FILE: byte 1234: ..."),
// which is what a user needs to act on them. An error that does not is a finding: the harness
// prints it and aborts, and libFuzzer keeps the input.
void expect_file_named(const Error& error, const std::string& path);

// Opens the file with open_rays() - as `format` when given, else by detection - and reads
// every ray. The errors a reader reports about a bad file (rayset::Error naming the file) are the
// expected outcome of most inputs; anything else (another exception, a crash, a sanitizer
// report) reaches libFuzzer.
void read_every_ray(const std::string& path, std::optional<RayFormat> format);

}  // namespace rayset::fuzz
