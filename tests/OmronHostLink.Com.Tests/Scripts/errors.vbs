' Err.Number and Err.Description of each kind of failure, against the simulator at WScript.Arguments(0).
' Prints name=number|description lines; Err.Number is decimal, as VB shows it.
Option Explicit
Dim endpoint, plc, other, value
endpoint = WScript.Arguments(0)

Sub Report(name)
    WScript.Echo name & "=" & Err.Number & "|" & Err.Description
    Err.Clear
End Sub

Set plc = CreateObject("OmronHostLink.Plc")
On Error Resume Next

value = plc.ReadWord("D100")
Report "NotOpen"

plc.Open "tcp://" & endpoint & ";TurnaroundAllowance=200ms;ReadRetries=0"
Report "Open"

plc.SetMode "RUN"
Report "SetModeRun"
plc.WriteWord "D200", 1
Report "WriteInRunMode"

plc.UnitNumber = 7
value = plc.ReadWord("D100")
Report "SilentUnit"
plc.UnitNumber = 0

value = plc.ReadWord("X100")
Report "BadAddress"
value = plc.ReadWords("D100", 0)
Report "BadCount"
plc.WriteWord "D200", 70000
Report "BadValue"
plc.SetMode "STOP"
Report "BadMode"
plc.UnitNumber = 32
value = plc.ReadWord("D100")
Report "BadUnit"
plc.UnitNumber = 0
plc.Open "tcp://" & endpoint
Report "OpenTwice"
plc.Close

Set other = CreateObject("OmronHostLink.Plc")
other.Open "COM3:9600,X,7,2"
Report "BadParity"
other.Open "tcp://127.0.0.1:99999"
Report "BadPort"
other.Open "tcp://127.0.0.1:1;TurnaroundAllowance=200ms"
Report "OpenRefused"
value = other.ReadWord("D100")
Report "ConnectionRefused"
other.Close
WScript.Echo "Done=yes"
