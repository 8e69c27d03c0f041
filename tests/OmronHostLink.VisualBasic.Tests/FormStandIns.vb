Imports System.Collections.Concurrent

''' <summary>What a WinForms Label gives the code under test: text, set on the UI thread.</summary>
Public NotInheritable Class Label
    Private ReadOnly _history As BlockingCollection(Of String)
    Private _text As String = ""

    ''' <param name="history">Where every text set is also recorded, for a test to wait on; Nothing for none.</param>
    Public Sub New(Optional history As BlockingCollection(Of String) = Nothing)
        _history = history
    End Sub

    Public Property Text As String
        Get
            Return _text
        End Get
        Set(value As String)
            TextThreadId = Environment.CurrentManagedThreadId
            _text = value
            _history?.Add(value)
        End Set
    End Property

    ''' <summary>The thread that last set the text.</summary>
    Public Property TextThreadId As Integer
End Class

''' <summary>What a WinForms Timer gives the code under test: a Tick raised on the UI thread.</summary>
Public NotInheritable Class Timer
    Public Event Tick As EventHandler

    ''' <summary>Raises Tick on the UI thread and waits for its handler, as the message loop does with WM_TIMER.</summary>
    Public Sub PerformTick(ui As UiThread)
        ui.Run(Sub() RaiseEvent Tick(Me, EventArgs.Empty), TimeSpan.FromSeconds(60))
    End Sub
End Class
