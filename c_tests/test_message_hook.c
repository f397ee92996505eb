/*
 * test_message_hook.c: ifl_set_message_handler (docs/c-api.md). A handler receives every
 * message instead of the INTERFACIAL_LOG file: 8 threads each make 500 refused ifl_fric_point
 * calls with a distinct cause (mu = -tag); every message arrives once, whole (it is the calling
 * thread's own ifl_last_error), with its length. The handler keeps its record without a lock:
 * the library calls it one call at a time, so nothing may be lost. After
 * ifl_set_message_handler(NULL, NULL) messages go to the file again (the harness counts the
 * file's lines: one before the handler, one after).
 */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"

enum { THREADS = 8, PER_THREAD = 500, TOTAL = THREADS * PER_THREAD, MSG = 240 };

typedef struct {
    int count;                  /* messages received (no lock: the calls are serialised) */
    int bad_len;                /* messages whose len differed from strlen */
    int in_call;                /* 1 while a call runs: a second one at the same time is caught */
    int overlaps;               /* calls that found another one running */
    char text[TOTAL + 8][MSG];  /* each message, cut to MSG - 1 bytes */
} record;

static record received;
static char sent[TOTAL][MSG];   /* each thread's own last error after its call */

static void on_message(const char *msg, size_t len, void *user)
{
    record *r = (record *)user;
    if (r->in_call) {
        r->overlaps++;
    }
    r->in_call = 1;
    if (len != strlen(msg)) {
        r->bad_len++;
    }
    if (r->count < TOTAL + 8) {
        snprintf(r->text[r->count], MSG, "%s", msg);
    }
    r->count++;
    r->in_call = 0;
}

/* A refused call whose message names tag: PROPS(2) = mu = -tag. */
static void bad_call(int tag, char *out)
{
    double props[2] = {1.0, -(double)tag};
    double statev[3] = {0.0, 0.0, 0.0};
    IflFricInput in;
    IflFricOutput res;
    memset(&in, 0, sizeof in);
    in.nfdir = 1;
    in.press = 10.0;
    in.dtime = 1.0;
    in.chrlngth = 1.0;
    in.drot[0] = in.drot[3] = 1.0;
    in.mcrd = 3;
    in.interaction = "HOOK";
    in.props = props;
    in.nprops = 2;
    in.statev = statev;
    in.nstatv = 3;
    in.pnewdt = 1e36;
    (void)ifl_fric_point(&in, &res);
    if (out != NULL) {
        snprintf(out, MSG, "%s", ifl_last_error());
    }
}

static void *worker(void *arg)
{
    int t = (int)(size_t)arg;
    for (int i = 0; i < PER_THREAD; i++) {
        int k = t * PER_THREAD + i;
        bad_call(1000 + k, sent[k]);
    }
    return NULL;
}

static int by_text(const void *a, const void *b)
{
    return strcmp((const char *)a, (const char *)b);
}

static int count_lines(const char *path)
{
    FILE *f = fopen(path, "r");
    int n = 0, c;
    if (f == NULL) {
        return -1;
    }
    while ((c = fgetc(f)) != EOF) {
        n += c == '\n';
    }
    fclose(f);
    return n;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: %s LOG (the INTERFACIAL_LOG file)\n", argv[0]);
        return 2;
    }
    remove(argv[1]);
    fh_context("before a handler: to the file");
    bad_call(1, NULL);
    FH_CHECK(count_lines(argv[1]) == 1);

    fh_context("8 threads, a handler");
    ifl_set_message_handler(on_message, &received);
    pthread_t th[THREADS];
    for (int t = 0; t < THREADS; t++) {
        FH_CHECK(pthread_create(&th[t], NULL, worker, (void *)(size_t)t) == 0);
    }
    for (int t = 0; t < THREADS; t++) {
        pthread_join(th[t], NULL);
    }
    FH_CHECK(received.count == TOTAL);
    FH_CHECK(received.bad_len == 0);
    FH_CHECK(received.overlaps == 0);
    /* Each message whole: the multiset received is the multiset the threads were told. */
    qsort(received.text, TOTAL, MSG, by_text);
    qsort(sent, TOTAL, MSG, by_text);
    int same = 0;
    for (int k = 0; k < TOTAL; k++) {
        same += strcmp(received.text[k], sent[k]) == 0 && strstr(sent[k], "HOOK") != NULL;
    }
    FH_CHECK(same == TOTAL);
    FH_CHECK(count_lines(argv[1]) == 1);

    fh_context("NULL: to the file again");
    ifl_set_message_handler(NULL, NULL);
    bad_call(2, NULL);
    FH_CHECK(received.count == TOTAL);
    FH_CHECK(count_lines(argv[1]) == 2);
    return fh_finish();
}
