' Events through WScript.ConnectObject, as on Windows: a watch whose ValueChanged, ConnectionLost and
' ConnectionRestored arrive on this thread while WScript.Sleep dispatches messages. Against the simulator at
' WScript.Arguments(0); the test changes D100 after "Ready" and stops the simulator after "Changed".
Option Explicit
Dim plc, phase, deadline
phase = "initial"

Sub plc_ValueChanged(tag, value)
    WScript.Echo "ValueChanged=" & phase & " " & tag & " " & value
    If phase = "ready" And tag = "D100" And value = 777 Then phase = "changed"
End Sub

Sub plc_ConnectionLost(number, description)
    WScript.Echo "ConnectionLost=" & number & "|" & description
    If phase = "changed" Then phase = "lost"
End Sub

Sub plc_ConnectionRestored(seconds)
    WScript.Echo "ConnectionRestored=" & (seconds >= 0)
End Sub

Sub WaitFor(wanted, seconds)
    deadline = DateAdd("s", seconds, Now)
    Do While phase <> wanted And Now < deadline
        WScript.Sleep 50
    Loop
    WScript.Echo "Phase=" & phase
End Sub

Set plc = CreateObject("OmronHostLink.Plc")
WScript.ConnectObject plc, "plc_"
plc.Open "tcp://" & WScript.Arguments(0) & ";TurnaroundAllowance=300ms;ReadRetries=0"
plc.Watch "D100", 100
deadline = DateAdd("s", 20, Now)
Do While Now < deadline
    WScript.Sleep 50
    If Not IsEmpty(plc.WatchedValue("D100")) Then Exit Do
Loop
WScript.Sleep 200
phase = "ready"
WScript.Echo "Ready=yes"
WaitFor "changed", 20
WaitFor "lost", 20
plc.StopWatch
plc.Close
WScript.Echo "Done=yes"
