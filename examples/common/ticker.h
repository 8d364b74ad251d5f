/* examples/common/ticker.h - a progress line on a terminal for a run whose
 * work happens inside one library call.
 *
 * The chapter programs hand all their samples to one estimator call, which
 * reports nothing until it returns. On a terminal a long run still shows
 * that it is alive and how far along it should be: a helper thread redraws
 * "prog: 12 s of about 40 s" on stderr once a second, and the line is
 * cleared when the program exits. The estimate is the one app_announce
 * printed; the elapsed time is measured.
 */
#ifndef APP_TICKER_H
#define APP_TICKER_H

/* Starts the line for a run estimated at `seconds`, once per process; does
 * nothing when stderr is not a terminal or a line is already running. */
void app_ticker_start(const char *prog, double seconds);

#endif /* APP_TICKER_H */
