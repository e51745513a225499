/* Which tests touch threads: preloaded (LD_PRELOAD) into the Release test run by
 * scripts/test.sh, this library notes every process that starts a thread or a child process
 * (a child may have threads of its own: a tlmhub-server, the CLI). The first time a process
 * does either it writes its command line to $TLMHUB_THREAD_PROBE_DIR/<pid>; the script then
 * matches those command lines to ctest's tests and checks that each such test has the label
 * `threads`, which always runs under TSan (scripts/ci/check_threads_label.py).
 * Without TLMHUB_THREAD_PROBE_DIR it only passes the calls on. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <fcntl.h>
#include <pthread.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

static void note_this_process(void)
{
    static int noted = 0;
    const char* dir = getenv("TLMHUB_THREAD_PROBE_DIR");
    if (noted || dir == NULL) return;
    noted = 1;
    char path[4096];
    snprintf(path, sizeof path, "%s/%ld", dir, (long)getpid());
    int in = open("/proc/self/cmdline", O_RDONLY);
    int out = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (in >= 0 && out >= 0) {
        char buffer[8192];
        ssize_t n;
        while ((n = read(in, buffer, sizeof buffer)) > 0)
            if (write(out, buffer, (size_t)n) != n) break;
    }
    if (in >= 0) close(in);
    if (out >= 0) close(out);
}

/* The next definition of `name` after this library (libc's). */
static void* next_symbol(const char* name)
{
    return dlsym(RTLD_NEXT, name);
}

int pthread_create(pthread_t* thread, const pthread_attr_t* attr, void* (*start)(void*), void* arg)
{
    static int (*real)(pthread_t*, const pthread_attr_t*, void* (*)(void*), void*) = NULL;
    if (real == NULL) real = next_symbol("pthread_create");
    note_this_process();
    return real(thread, attr, start, arg);
}

pid_t fork(void)
{
    static pid_t (*real)(void) = NULL;
    if (real == NULL) real = next_symbol("fork");
    note_this_process();
    return real();
}

/* Python's subprocess starts its children with vfork. fork in its place does the same for a
 * child that execs at once, and unlike vfork lets this wrapper return in the child. */
pid_t vfork(void)
{
    static pid_t (*real)(void) = NULL;
    if (real == NULL) real = next_symbol("fork");
    note_this_process();
    return real();
}

/* posix_spawn and posix_spawnp differ only in how they find the program. */
typedef int (*spawn_function)(pid_t*, const char*, const posix_spawn_file_actions_t*, const posix_spawnattr_t*,
                              char* const[], char* const[]);

static int spawn_through(const char* name, spawn_function* real, pid_t* pid, const char* program,
                         const posix_spawn_file_actions_t* actions, const posix_spawnattr_t* attributes,
                         char* const argv[], char* const envp[])
{
    if (*real == NULL) *real = (spawn_function)next_symbol(name);
    note_this_process();
    return (*real)(pid, program, actions, attributes, argv, envp);
}

int posix_spawn(pid_t* pid, const char* path, const posix_spawn_file_actions_t* actions,
                const posix_spawnattr_t* attributes, char* const argv[], char* const envp[])
{
    static spawn_function real = NULL;
    return spawn_through("posix_spawn", &real, pid, path, actions, attributes, argv, envp);
}

int posix_spawnp(pid_t* pid, const char* file, const posix_spawn_file_actions_t* actions,
                 const posix_spawnattr_t* attributes, char* const argv[], char* const envp[])
{
    static spawn_function real = NULL;
    return spawn_through("posix_spawnp", &real, pid, file, actions, attributes, argv, envp);
}

/* popen and system start their child inside libc, past the symbols above. */
FILE* popen(const char* command, const char* mode)
{
    static FILE* (*real)(const char*, const char*) = NULL;
    if (real == NULL) real = next_symbol("popen");
    note_this_process();
    return real(command, mode);
}

int system(const char* command)
{
    static int (*real)(const char*) = NULL;
    if (real == NULL) real = next_symbol("system");
    note_this_process();
    return real(command);
}
