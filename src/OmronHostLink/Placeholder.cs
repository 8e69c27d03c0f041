namespace OmronHostLink;
internal static class Placeholder { }
