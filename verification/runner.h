/* slipfield verification: the `slipfield verify` command (runner.c). */
#ifndef SF_RUNNER_H
#define SF_RUNNER_H
/* `slipfield verify ...`: argv[0] is "verify".  Returns the exit status. */
int sf_verify_main(int argc, char **argv);
#endif
