/* Lets Wine's serial layer use a pseudo-terminal: answers the modem and line-status ioctls a pty refuses. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <stdarg.h>
#include <string.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <linux/serial.h>

static int (*real_ioctl)(int, unsigned long, void *);
static int (*real_tcsetattr)(int, int, const struct termios *);

int ioctl(int fd, unsigned long request, ...)
{
    va_list args;
    va_start(args, request);
    void *arg = va_arg(args, void *);
    va_end(args);
    if (!real_ioctl) real_ioctl = dlsym(RTLD_NEXT, "ioctl");
    int saved = errno;
    int result = real_ioctl(fd, request, arg);
    if (result == -1 && (errno == EINVAL || errno == ENOTTY || errno == EIO))
    {
        switch (request)
        {
        case TIOCMGET: *(int *)arg = TIOCM_DSR | TIOCM_CTS | TIOCM_CAR; errno = saved; return 0;
        case TIOCMSET: case TIOCMBIS: case TIOCMBIC: errno = saved; return 0;
        case TIOCGICOUNT: memset(arg, 0, sizeof(struct serial_icounter_struct)); errno = saved; return 0;
        case TIOCSERGETLSR: *(unsigned int *)arg = TIOCSER_TEMT; errno = saved; return 0;
        }
    }
    return result;
}

int tcsetattr(int fd, int actions, const struct termios *termios)
{
    if (!real_tcsetattr) real_tcsetattr = dlsym(RTLD_NEXT, "tcsetattr");
    int result = real_tcsetattr(fd, actions, termios);
    if (result == -1 && errno == EINVAL) { errno = 0; return 0; }
    return result;
}
