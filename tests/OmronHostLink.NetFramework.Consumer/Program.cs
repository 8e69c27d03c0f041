using System;
using System.Threading;
using OmronHostLink;

namespace OmronHostLink.NetFramework.Consumer
{
    /// <summary>What a .NET Framework 4.8 service or WinForms app written in C# 7.3 does with the library.</summary>
    internal static class Program
    {
        private static int Main(string[] args)
        {
            string portName = args.Length > 0 ? args[0] : "COM3";
            using (var plc = HostLinkClient.ForSerialPort(portName))
            {
                try
                {
                    ushort[] dm = plc.ReadWords("D100", 10);
                    float temperature = plc.Read<float>("D200");
                    int setpoint = plc.ReadBcd("D210");
                    plc.WriteWords("D300", 1, 2, 3);
                    bool running = plc.ReadBit("CIO 100.05");
                    plc.Unit(0, HostLinkCommandSet.Fins).WriteBit("W400.07", true);
                    PlcStatus status = plc.ReadStatus();

                    // The Task-returning methods block just as well: Result, Wait() and GetAwaiter().GetResult().
                    ushort first = plc.ReadWordsAsync("D100", 1).Result[0];
                    plc.WriteWordAsync("D301", first).Wait();
                    PlcModel model = plc.ReadModelAsync().GetAwaiter().GetResult();

                    Console.WriteLine("{0} {1} {2} {3} {4} {5}", dm[0], temperature, setpoint, running, status.Mode, model);
                }
                catch (HostLinkEndCodeException e) when (e.EndCode == EndCode.NotExecutableInRunMode)
                {
                    Console.Error.WriteLine("Switch the PLC to MONITOR mode to write: " + e.Message);
                    return 3;
                }
                catch (HostLinkException e)
                {
                    Console.Error.WriteLine(e.Message);
                    return 4;
                }
            }

            using (var component = new HostLinkPlc())
            using (var stop = new ManualResetEventSlim())
            {
                component.PortName = portName;
                component.Tags = new[] { "D100", "D200:float", "CIO 10.03" };
                component.Interval = 500;
                component.ValueChanged += (sender, e) => Console.WriteLine("{0} = {1}", e.TagText, e.NewValue);
                component.ConnectionLost += (sender, e) => Console.WriteLine("PLC not answering: " + e.Exception.Message);
                component.Error += (sender, e) => Console.WriteLine("A handler failed: " + e.Exception.Message);
                component.Start();
                stop.Wait(TimeSpan.FromSeconds(5));
            }

            return 0;
        }
    }
}
