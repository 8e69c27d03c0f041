' Every method and property of OmronHostLink.Plc, against the simulator at WScript.Arguments(0) (host:port), unit 00
' and unit 01. Prints name=value lines; the test checks them against the simulator's memory, which it set and reads.
Option Explicit
Dim endpoint, plc, words, status, values, i, text
endpoint = WScript.Arguments(0)

Sub Report(name, value)
    WScript.Echo name & "=" & value
End Sub

Function Joined(items)
    Dim j, s
    s = ""
    For j = LBound(items) To UBound(items)
        If j > LBound(items) Then s = s & " "
        s = s & items(j)
    Next
    Joined = s
End Function

Set plc = CreateObject("OmronHostLink.Plc")
Report "IsOpenBefore", plc.IsOpen
plc.Open "tcp://" & endpoint & ";TurnaroundAllowance=2000ms;ReadRetries=1"
Report "IsOpen", plc.IsOpen
Report "Description", plc.Description
Report "Host", plc.Host
Report "TcpPort", plc.TcpPort
Report "PortName", plc.PortName
Report "UnitNumber", plc.UnitNumber
Report "CommandSet", plc.CommandSet
Report "BaudRate", plc.BaudRate
Report "Parity", plc.Parity
Report "DataBits", plc.DataBits
Report "StopBits", plc.StopBits
Report "TurnaroundAllowance", plc.TurnaroundAllowance
Report "ReadRetries", plc.ReadRetries

words = plc.ReadWords("D100", 10)
Report "ReadWords", Joined(words)
Report "ReadWordsType", TypeName(words(0))
Report "ReadWord", plc.ReadWord("D105")
Report "ReadBit", plc.ReadBit("D120.03")
Report "ReadReal", plc.ReadReal("D130")
Report "ReadRealType", TypeName(plc.ReadReal("D130"))
Report "ReadBcd", plc.ReadBcd("D150")
Report "ReadLReal", plc.ReadLReal("D160")
Report "ReadDint", plc.ReadDint("D170")
Report "ReadString", plc.ReadString("D180", 8)
Report "Read", plc.Read("D130:float")
Report "ReadTags", Joined(plc.ReadTags(Array("D100", "D130:float", "D150:bcd", "D120.03")))
Report "ReadMode", plc.ReadMode()

' C-mode writes need MONITOR (or PROGRAM) mode.
plc.SetMode "MONITOR"
Report "SetMode", plc.ReadMode()
plc.WriteWord "D200", 4321
Report "WriteWord", plc.ReadWord("D200")
plc.WriteWords "D210", Array(1, 2, 65535, -1)
Report "WriteWords", Joined(plc.ReadWords("D210", 4))
plc.WriteReal "D140", 2.5
Report "WriteReal", plc.ReadReal("D140")
plc.WriteBcd "D152", 5678
Report "WriteBcd", plc.ReadBcd("D152")
plc.WriteLReal "D164", 0.125
Report "WriteLReal", plc.ReadLReal("D164")
plc.WriteDint "D172", -123456
Report "WriteDint", plc.ReadDint("D172")
plc.WriteString "D190", "HELLO"
Report "WriteString", plc.ReadString("D190", 5)
plc.Write "D194:int16", -5
Report "Write", plc.Read("D194:int16")

Set status = plc.ReadStatus()
Report "ReadStatus", status.Mode & " " & status.StatusWord & " [" & status.Message & "]"
Report "ReadErrors", plc.ReadErrors()
Report "ReadErrorsClear", plc.ReadErrors(True)
Report "ReadModel", plc.ReadModel()
Report "Test", plc.Test() > 0

' Another unit on the same line: the same object, another UnitNumber.
plc.UnitNumber = 1
Report "Unit1", plc.ReadWord("D100")
plc.UnitNumber = 0
Report "Unit0", plc.ReadWord("D100")
plc.Close
Report "IsOpenAfter", plc.IsOpen

' FINS for bits: C-mode has no bit write.
plc.Open "tcp://" & endpoint & ";CommandSet=Fins"
plc.WriteBit "W10.05", True
Report "WriteBit", plc.ReadBit("W10.05")
plc.Close

' The same link from properties instead of a connection string.
Dim parts
parts = Split(endpoint, ":")
plc.Host = parts(0)
plc.TcpPort = CLng(parts(1))
plc.UnitNumber = 1
plc.Open
Report "Properties", plc.Description & " unit " & plc.UnitNumber & " " & plc.ReadWord("D100")
plc.Close
Report "Done", "yes"
