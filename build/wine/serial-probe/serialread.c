#include <windows.h>
#include <stdio.h>
int main(int argc, char **argv)
{
    const char *port = argc > 1 ? argv[1] : "\\\\.\\COM9";
    int mode = argc > 2 ? atoi(argv[2]) : 0;
    HANDLE h = CreateFileA(port, GENERIC_READ | GENERIC_WRITE, 0, NULL, OPEN_EXISTING, FILE_FLAG_OVERLAPPED, NULL);
    if (h == INVALID_HANDLE_VALUE) { printf("open failed %lu\n", GetLastError()); return 1; }
    DCB dcb = { sizeof(dcb) };
    GetCommState(h, &dcb);
    dcb.BaudRate = 9600; dcb.ByteSize = 7; dcb.Parity = EVENPARITY; dcb.StopBits = TWOSTOPBITS; dcb.fBinary = TRUE; dcb.fParity = TRUE;
    printf("SetCommState %d (%lu)\n", SetCommState(h, &dcb), GetLastError());
    COMMTIMEOUTS t = {0};
    if (mode == 0) { t.ReadIntervalTimeout = MAXDWORD; t.ReadTotalTimeoutMultiplier = MAXDWORD; t.ReadTotalTimeoutConstant = 0xFFFFFFFE; }
    else if (mode == 1) { t.ReadIntervalTimeout = MAXDWORD; t.ReadTotalTimeoutMultiplier = MAXDWORD; t.ReadTotalTimeoutConstant = 5000; }
    else if (mode == 2) { t.ReadIntervalTimeout = 10; t.ReadTotalTimeoutMultiplier = 0; t.ReadTotalTimeoutConstant = 0; }
    printf("SetCommTimeouts %d (%lu) mode %d\n", SetCommTimeouts(h, &t), GetLastError(), mode);
    printf("SetCommMask %d\n", SetCommMask(h, EV_RXCHAR | EV_ERR | EV_BREAK | EV_CTS | EV_DSR | EV_RING | EV_RLSD | EV_RXFLAG));
    char buf[64]; DWORD got = 0;
    OVERLAPPED ov = {0}; ov.hEvent = CreateEventA(NULL, TRUE, FALSE, NULL);
    BOOL ok = ReadFile(h, buf, sizeof(buf), &got, &ov);
    DWORD err = GetLastError();
    printf("ReadFile immediate ok=%d got=%lu err=%lu\n", ok, got, err); fflush(stdout);
    if (!ok && err == ERROR_IO_PENDING) {
        DWORD w = WaitForSingleObject(ov.hEvent, 8000);
        ok = GetOverlappedResult(h, &ov, &got, FALSE);
        printf("wait=%lu ok=%d got=%lu err=%lu\n", w, ok, got, GetLastError());
    }
    if (got) { buf[got] = 0; printf("data: %s\n", buf); }
    fflush(stdout);
    return 0;
}
