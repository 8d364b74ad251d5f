/* lab/gsl_config.h - the config.h that GSL's sources include, written by
 * hand for clang's wasm32-wasi target (wasi-libc), in place of the one
 * GSL's configure script would write: the lab compiles a handful of GSL's
 * files (adaptive quadrature, the chi-square tail and what they call), not
 * the whole library, so running configure for a cross target is not worth
 * its minute. Every macro here states a fact of wasi-libc or of
 * WebAssembly's IEEE 754 doubles. */
#ifndef LAB_GSL_CONFIG_H
#define LAB_GSL_CONFIG_H

/* wasi-libc (musl) declares all of C99's math. */
#define HAVE_DECL_ACOSH 1
#define HAVE_DECL_ASINH 1
#define HAVE_DECL_ATANH 1
#define HAVE_DECL_EXPM1 1
#define HAVE_DECL_FINITE 0
#define HAVE_DECL_FREXP 1
#define HAVE_DECL_HYPOT 1
#define HAVE_DECL_ISFINITE 1
#define HAVE_DECL_ISINF 1
#define HAVE_DECL_ISNAN 1
#define HAVE_DECL_LDEXP 1
#define HAVE_DECL_LOG1P 1
#define HAVE_DECL_FEENABLEEXCEPT 0
#define HAVE_DECL_FESETTRAPENABLE 0
#define HAVE_EXIT_SUCCESS_AND_FAILURE 1
#define HAVE_INTTYPES_H 1
#define HAVE_STDINT_H 1
#define HAVE_STDIO_H 1
#define HAVE_STDLIB_H 1
#define HAVE_STRING_H 1
#define HAVE_MEMCPY 1
#define HAVE_MEMMOVE 1
#define HAVE_VPRINTF 1
#define STDC_HEADERS 1

/* WebAssembly's f64 is IEEE binary64 with denormals and no wider
 * registers: comparisons are IEEE's and no value needs coercing to
 * double. */
#define HAVE_IEEE_COMPARISONS 1
#define HAVE_IEEE_DENORMALS 1
#define HAVE_EXTENDED_PRECISION_REGISTERS 0
#define GSL_COERCE_DBL(x) (x)

/* GSL's own inline functions stay out-of-line, as in Debian's build of
 * the library the native programs link. */
#define RETURN_IF_NULL(x) if (!(x)) { return; }

#define PACKAGE_VERSION "2.7.1"
#define VERSION "2.7.1"

#endif /* LAB_GSL_CONFIG_H */
