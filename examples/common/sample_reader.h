/* examples/common/sample_reader.h - the points of a sample file, for
 * `mcbox-check --samples`: a sampler written in any language writes its
 * points to a file and mcbox checks them against a density (chapter 5,
 * Generating Random Directions, and every sampler after it).
 *
 * The parser works on a buffer in memory, never on a file, so that a
 * fuzzer can drive it; it never reads outside buf[0 .. len) and allocates
 * one array of points, of at most len + 1 doubles (a text coordinate takes
 * at least two bytes with its separator, and the array at most doubles
 * when it grows; a raw coordinate takes four or eight).
 *
 * Text: one sample per line, `dims` numbers separated by spaces, tabs or a
 * comma (with spaces around it or not). Lines that are blank or whose first
 * non-blank character is '#' are skipped; so is the first other line when
 * none of its fields is a number (a header such as "x,y,z"). CRLF line
 * ends are accepted, a UTF-8 byte-order mark at the start is skipped, a
 * UTF-16 one is refused, and so is a control byte other than blanks and
 * line ends in the first 4 KiB ("looks binary": raw records read as
 * text). Only points: a pdf or weight column is an error.
 * Raw: records of `dims` little-endian IEEE-754 float32 or float64 values,
 * nothing else (no header).
 *
 * A non-finite coordinate (NaN, inf, or a number too large for a double)
 * is bad input here, not a sample: a file that holds one was written
 * wrongly.
 */
#ifndef APP_SAMPLE_READER_H
#define APP_SAMPLE_READER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

typedef enum app_samples_format {
    APP_SAMPLES_TEXT, /* "csv" on the command line: any of the separators above */
    APP_SAMPLES_F32,  /* "f32" */
    APP_SAMPLES_F64   /* "f64" */
} app_samples_format;

/* The longest text line accepted, without its line end: 1 MiB. A longer
 * line is refused before it is split, so a line of a million columns
 * costs one pass over it. */
#define APP_SAMPLES_MAX_LINE (1u << 20)

/* The format called `name` ("csv", "f32", "f64") into *f; false when
 * unknown. */
bool app_samples_format_parse(const char *name, app_samples_format *f);

/* Parses buf[0 .. len) as samples of `dims` (1 .. 3) coordinates. On
 * success returns true, *points holds n * dims doubles (sample i at
 * (*points)[i * dims ...], to be released with free) and *n >= 1. On
 * failure returns false, sets *points to NULL and writes one line (no
 * newline) to err: "line L: ..." for text, "sample K (byte B): ..." for
 * raw records (lines and samples counted from 1, byte offsets from 0), or
 * what is wrong with the whole buffer ("no samples ...", "looks binary
 * ...", "out of memory"). */
bool app_samples_parse(const char *buf, size_t len, app_samples_format fmt, int dims,
                       double **points, uint64_t *n, char *err, size_t errlen);

#endif /* APP_SAMPLE_READER_H */
