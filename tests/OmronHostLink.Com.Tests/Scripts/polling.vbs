' The polling pattern, without events: Watch, then WaitForChanges and WatchedValue. Against the simulator at
' WScript.Arguments(0); waits for the test to change D100 after "Ready".
Option Explicit
Dim plc, changed, tag, deadline, seen
Set plc = CreateObject("OmronHostLink.Plc")
plc.Open "tcp://" & WScript.Arguments(0)
plc.Watch Array("D100", "D130:float"), 100
WScript.Echo "IsWatching=" & plc.IsWatching

' The first read reports every tag once.
seen = ""
Do While InStr(seen, "D130:float") = 0 Or InStr(seen, "D100;") = 0
    For Each tag In plc.WaitForChanges(10000)
        seen = seen & tag & ";"
        WScript.Echo "Initial=" & tag & " " & plc.WatchedValue(tag)
    Next
Loop
WScript.Echo "Ready=yes"

Do
    changed = plc.WaitForChanges(20000)
    If UBound(changed) < 0 Then
        WScript.Echo "Timeout=yes"
        Exit Do
    End If
    For Each tag In changed
        WScript.Echo "Changed=" & tag & " " & plc.WatchedValue(tag)
    Next
    If plc.WatchedValue("D100") = 777 Then Exit Do
Loop
WScript.Echo "WatchError=[" & plc.WatchError & "]"
plc.StopWatch
WScript.Echo "StoppedWatching=" & plc.IsWatching
plc.Close
