namespace OmronHostLink.Com.Tests;

/// <summary>
/// The Err.Number table of docs/migrating.md ("Errors: Err.Number"), written out here as the documentation states it,
/// so the tests check the server against what a VB programmer was told rather than against the server's own constants.
/// </summary>
internal static class Documented
{
    public const int Timeout = unchecked((int)0x80040201);
    public const int Frame = unchecked((int)0x80040202);
    public const int Connection = unchecked((int)0x80040203);
    public const int NotOpen = unchecked((int)0x80040204);
    public const int InvalidArgument = unchecked((int)0x80040205);
    public const int HostLink = unchecked((int)0x80040206);
    public const int EndCode = unchecked((int)0x80041000);
    public const int EndCodeRunMode = unchecked((int)0x80041001);
    public const int FinsEndCode = unchecked((int)0x80048000);
}
