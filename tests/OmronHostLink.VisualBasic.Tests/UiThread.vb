Imports System.Collections.Concurrent
Imports System.Threading

''' <summary>
''' A UI thread stand-in: one thread pumping posted callbacks with itself as the thread's SynchronizationContext, as a
''' WinForms message loop is. An exception a callback throws is handed to ThreadException (WinForms'
''' Application.ThreadException) and the pump goes on.
''' </summary>
Public NotInheritable Class UiThread
    Inherits SynchronizationContext
    Implements IDisposable

    Private ReadOnly _queue As New BlockingCollection(Of Action)()
    Private ReadOnly _thread As Thread

    Public Sub New()
        _thread = New Thread(AddressOf Pump) With {.IsBackground = True, .Name = "VB UI thread stand-in"}
        _thread.Start()
    End Sub

    ''' <summary>Exceptions thrown by callbacks, in order.</summary>
    Public ReadOnly Property ThreadExceptions As New BlockingCollection(Of Exception)()

    Public ReadOnly Property ThreadId As Integer
        Get
            Return _thread.ManagedThreadId
        End Get
    End Property

    Public Overrides Sub Post(d As SendOrPostCallback, state As Object)
        _queue.Add(Sub() d(state))
    End Sub

    ''' <summary>Runs <paramref name="action"/> on the UI thread and waits (at most <paramref name="limit"/>: longer is a deadlock).</summary>
    Public Sub Run(action As Action, limit As TimeSpan)
        Dim finished As New TaskCompletionSource(Of Boolean)(TaskCreationOptions.RunContinuationsAsynchronously)
        _queue.Add(Sub()
                       Try
                           action()
                           finished.SetResult(True)
                       Catch ex As Exception
                           finished.SetException(ex)
                       End Try
                   End Sub)
        If Not finished.Task.Wait(limit) Then
            Throw New TimeoutException($"The UI thread was still busy after {limit}: a deadlock.")
        End If
        finished.Task.GetAwaiter().GetResult()
    End Sub

    Public Sub Dispose() Implements IDisposable.Dispose
        _queue.CompleteAdding()
    End Sub

    Private Sub Pump()
        SetSynchronizationContext(Me)
        For Each callback In _queue.GetConsumingEnumerable()
            Try
                callback()
            Catch ex As Exception
                ThreadExceptions.Add(ex)
            End Try
        Next
    End Sub
End Class
