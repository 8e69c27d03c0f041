/*
 * scripthost: runs a VBScript file the way cscript.exe does, for the COM server's tests under Wine.
 *
 * Wine's own cscript runs scripts and prints WScript.Echo, but answers WScript.ConnectObject, WScript.CreateObject
 * with a prefix and WScript.Sleep with E_NOTIMPL. This host gives a script those three as Windows Script Host does:
 * ConnectObject finds the object's default source interface through IProvideClassInfo, advises a sink on its
 * connection point and calls the script's Sub <prefix><EventName> for each event, by the event's name in the type
 * information; Sleep waits while dispatching the thread's messages, which is when an apartment-threaded object's
 * events arrive. It also has WScript.Echo, WScript.Arguments (Item, Count, Length), WScript.Quit and
 * WScript.DisconnectObject. An event that arrives on any other thread than the script's is refused with
 * RPC_E_WRONG_THREAD and reported, since an apartment-threaded engine may only be called on its own thread.
 *
 * Usage: scripthost.exe script.vbs [arguments...]. Exit code: the code given to WScript.Quit, 0 when the script
 * ends, 1 when it stops on an error (printed to stderr as cscript prints it: file, line, column, description, number).
 */
#define COBJMACROS
#define CINTERFACE
#define CONST_VTABLE
#include <windows.h>
#include <ole2.h>
#include <olectl.h>
#include <initguid.h>
#include <activscp.h>
#include <stdio.h>
#include <stdlib.h>
#include <wchar.h>

/* VBScript's CLSID: {B54F3741-5B07-11CF-A4B0-00AA004A55E8}. */
static const CLSID CLSID_VBScriptEngine = {0xb54f3741, 0x5b07, 0x11cf, {0xa4, 0xb0, 0x00, 0xaa, 0x00, 0x4a, 0x55, 0xe8}};

static IActiveScript *g_engine;
static WCHAR g_script_path[MAX_PATH];
static int g_argc;
static WCHAR **g_argv;
static int g_failed;
static DWORD g_script_thread;

/* ---- output ---- */

static void write_utf8(FILE *stream, const WCHAR *text, int length)
{
    int size = WideCharToMultiByte(CP_UTF8, 0, text, length, NULL, 0, NULL, NULL);
    char *buffer = malloc(size + 1);
    WideCharToMultiByte(CP_UTF8, 0, text, length, buffer, size, NULL, NULL);
    fwrite(buffer, 1, size, stream);
    free(buffer);
}

static void print_line(FILE *stream, const WCHAR *text)
{
    write_utf8(stream, text, (int)wcslen(text));
    fputc('\n', stream);
    fflush(stream);
}

/* ---- names and dispatch helpers ---- */

typedef struct
{
    const WCHAR *name;
    DISPID id;
} member;

static HRESULT find_ids(const member *members, int count, LPOLESTR *names, UINT name_count, DISPID *ids)
{
    HRESULT hr = S_OK;
    for (UINT i = 0; i < name_count; i++)
    {
        ids[i] = DISPID_UNKNOWN;
        if (i > 0)
        {
            hr = DISP_E_UNKNOWNNAME; /* named arguments are not supported */
            continue;
        }
        for (int m = 0; m < count; m++)
        {
            if (_wcsicmp(names[i], members[m].name) == 0)
            {
                ids[i] = members[m].id;
            }
        }
        if (ids[i] == DISPID_UNKNOWN)
        {
            hr = DISP_E_UNKNOWNNAME;
        }
    }
    return hr;
}

/* Arguments arrive last first; a VBScript variable is passed by reference. */
static VARIANT *argument(DISPPARAMS *params, UINT index)
{
    VARIANT *v = &params->rgvarg[params->cArgs - 1 - index];
    while (V_VT(v) == (VT_BYREF | VT_VARIANT))
    {
        v = V_VARIANTREF(v);
    }
    return v;
}

static HRESULT argument_as(DISPPARAMS *params, UINT index, VARTYPE type, VARIANT *out)
{
    VariantInit(out);
    return VariantChangeType(out, argument(params, index), 0, type);
}

static void set_exception(EXCEPINFO *info, const WCHAR *description, HRESULT hr)
{
    if (info)
    {
        memset(info, 0, sizeof(*info));
        info->bstrSource = SysAllocString(L"scripthost");
        info->bstrDescription = SysAllocString(description);
        info->scode = hr;
    }
}

/* ---- event sink: one per connected object ---- */

typedef struct
{
    IDispatch IDispatch_iface;
    LONG refs;
    IID source_iid;
    ITypeInfo *source_info;
    WCHAR prefix[128];
} sink;

static inline sink *sink_from(IDispatch *iface)
{
    return CONTAINING_RECORD(iface, sink, IDispatch_iface);
}

static HRESULT STDMETHODCALLTYPE sink_QueryInterface(IDispatch *iface, REFIID riid, void **out)
{
    sink *This = sink_from(iface);
    if (IsEqualIID(riid, &IID_IUnknown) || IsEqualIID(riid, &IID_IDispatch) || IsEqualIID(riid, &This->source_iid))
    {
        *out = iface;
        IDispatch_AddRef(iface);
        return S_OK;
    }
    *out = NULL;
    return E_NOINTERFACE;
}

static ULONG STDMETHODCALLTYPE sink_AddRef(IDispatch *iface)
{
    return InterlockedIncrement(&sink_from(iface)->refs);
}

static ULONG STDMETHODCALLTYPE sink_Release(IDispatch *iface)
{
    sink *This = sink_from(iface);
    LONG refs = InterlockedDecrement(&This->refs);
    if (refs == 0)
    {
        ITypeInfo_Release(This->source_info);
        free(This);
    }
    return refs;
}

static HRESULT STDMETHODCALLTYPE sink_GetTypeInfoCount(IDispatch *iface, UINT *count)
{
    *count = 0;
    return S_OK;
}

static HRESULT STDMETHODCALLTYPE sink_GetTypeInfo(IDispatch *iface, UINT index, LCID lcid, ITypeInfo **info)
{
    return E_NOTIMPL;
}

static HRESULT STDMETHODCALLTYPE sink_GetIDsOfNames(IDispatch *iface, REFIID riid, LPOLESTR *names, UINT count, LCID lcid, DISPID *ids)
{
    return E_NOTIMPL;
}

/* An event: its name from the source interface's type information, then the script's Sub <prefix><name>. */
static HRESULT STDMETHODCALLTYPE sink_Invoke(IDispatch *iface, DISPID id, REFIID riid, LCID lcid, WORD flags,
    DISPPARAMS *params, VARIANT *result, EXCEPINFO *info, UINT *arg_error)
{
    sink *This = sink_from(iface);
    BSTR name = NULL;
    if (GetCurrentThreadId() != g_script_thread)
    {
        /* The script engine is apartment-threaded: an event must come on the script's own thread. */
        fprintf(stderr, "scripthost: event %ld raised on thread %lu; the script runs on thread %lu\n", (long)id,
            (unsigned long)GetCurrentThreadId(), (unsigned long)g_script_thread);
        fflush(stderr);
        g_failed = 1;
        return RPC_E_WRONG_THREAD;
    }
    UINT found = 0;
    HRESULT hr = ITypeInfo_GetNames(This->source_info, id, &name, 1, &found);
    if (FAILED(hr) || found == 0)
    {
        return S_OK; /* an event the type information does not name: nothing to call */
    }

    WCHAR handler[256];
    _snwprintf(handler, 256, L"%s%s", This->prefix, name);
    handler[255] = 0;
    SysFreeString(name);

    IDispatch *script = NULL;
    hr = IActiveScript_GetScriptDispatch(g_engine, NULL, &script);
    if (FAILED(hr))
    {
        return hr;
    }

    LPOLESTR handler_name = handler;
    DISPID handler_id;
    hr = IDispatch_GetIDsOfNames(script, &IID_NULL, &handler_name, 1, 0, &handler_id);
    if (SUCCEEDED(hr))
    {
        DISPPARAMS call = {params->rgvarg, NULL, params->cArgs, 0};
        hr = IDispatch_Invoke(script, handler_id, &IID_NULL, 0, DISPATCH_METHOD, &call, NULL, NULL, NULL);
    }
    else
    {
        hr = S_OK; /* the script has no handler for this event: Windows Script Host ignores it too */
    }
    IDispatch_Release(script);
    return hr;
}

static const IDispatchVtbl sink_vtbl = {
    sink_QueryInterface, sink_AddRef, sink_Release,
    sink_GetTypeInfoCount, sink_GetTypeInfo, sink_GetIDsOfNames, sink_Invoke,
};

/* ---- connections made by ConnectObject ---- */

typedef struct connection
{
    IUnknown *object;
    IConnectionPoint *point;
    DWORD cookie;
    struct connection *next;
} connection;

static connection *g_connections;

/* The default source interface of the object's class, as Windows Script Host finds it. */
static HRESULT default_source(IDispatch *object, ITypeInfo **source)
{
    IProvideClassInfo *provide = NULL;
    ITypeInfo *class_info = NULL;
    TYPEATTR *attr = NULL;
    HRESULT hr = IDispatch_QueryInterface(object, &IID_IProvideClassInfo, (void **)&provide);
    if (FAILED(hr))
    {
        return hr;
    }
    hr = IProvideClassInfo_GetClassInfo(provide, &class_info);
    IProvideClassInfo_Release(provide);
    if (FAILED(hr))
    {
        return hr;
    }
    hr = ITypeInfo_GetTypeAttr(class_info, &attr);
    if (SUCCEEDED(hr))
    {
        hr = CONNECT_E_NOCONNECTION;
        for (UINT i = 0; i < attr->cImplTypes; i++)
        {
            INT impl_flags = 0;
            HREFTYPE ref;
            if (SUCCEEDED(ITypeInfo_GetImplTypeFlags(class_info, i, &impl_flags))
                && (impl_flags & (IMPLTYPEFLAG_FDEFAULT | IMPLTYPEFLAG_FSOURCE)) == (IMPLTYPEFLAG_FDEFAULT | IMPLTYPEFLAG_FSOURCE)
                && SUCCEEDED(ITypeInfo_GetRefTypeOfImplType(class_info, i, &ref)))
            {
                hr = ITypeInfo_GetRefTypeInfo(class_info, ref, source);
                break;
            }
        }
        ITypeInfo_ReleaseTypeAttr(class_info, attr);
    }
    ITypeInfo_Release(class_info);
    return hr;
}

static HRESULT connect_object(IDispatch *object, const WCHAR *prefix)
{
    ITypeInfo *source = NULL;
    TYPEATTR *attr = NULL;
    IConnectionPointContainer *container = NULL;
    IConnectionPoint *point = NULL;
    HRESULT hr = default_source(object, &source);
    if (FAILED(hr))
    {
        return hr;
    }
    sink *s = calloc(1, sizeof(*s));
    s->IDispatch_iface.lpVtbl = &sink_vtbl;
    s->refs = 1;
    s->source_info = source;
    wcsncpy(s->prefix, prefix, 127);
    hr = ITypeInfo_GetTypeAttr(source, &attr);
    if (SUCCEEDED(hr))
    {
        s->source_iid = attr->guid;
        ITypeInfo_ReleaseTypeAttr(source, attr);
        hr = IDispatch_QueryInterface(object, &IID_IConnectionPointContainer, (void **)&container);
    }
    if (SUCCEEDED(hr))
    {
        hr = IConnectionPointContainer_FindConnectionPoint(container, &s->source_iid, &point);
        IConnectionPointContainer_Release(container);
    }
    DWORD cookie = 0;
    if (SUCCEEDED(hr))
    {
        hr = IConnectionPoint_Advise(point, (IUnknown *)&s->IDispatch_iface, &cookie);
    }
    if (SUCCEEDED(hr))
    {
        connection *c = calloc(1, sizeof(*c));
        IDispatch_QueryInterface(object, &IID_IUnknown, (void **)&c->object);
        c->point = point;
        c->cookie = cookie;
        c->next = g_connections;
        g_connections = c;
    }
    else if (point)
    {
        IConnectionPoint_Release(point);
    }
    IDispatch_Release(&s->IDispatch_iface);
    return hr;
}

static HRESULT disconnect_object(IDispatch *object)
{
    IUnknown *identity = NULL;
    IDispatch_QueryInterface(object, &IID_IUnknown, (void **)&identity);
    HRESULT hr = S_OK;
    for (connection **c = &g_connections; *c;)
    {
        if ((*c)->object == identity)
        {
            connection *gone = *c;
            *c = gone->next;
            hr = IConnectionPoint_Unadvise(gone->point, gone->cookie);
            IConnectionPoint_Release(gone->point);
            IUnknown_Release(gone->object);
            free(gone);
        }
        else
        {
            c = &(*c)->next;
        }
    }
    if (identity)
    {
        IUnknown_Release(identity);
    }
    return hr;
}

static void disconnect_all(void)
{
    while (g_connections)
    {
        connection *gone = g_connections;
        g_connections = gone->next;
        IConnectionPoint_Unadvise(gone->point, gone->cookie);
        IConnectionPoint_Release(gone->point);
        IUnknown_Release(gone->object);
        free(gone);
    }
}

/* ---- WScript.Sleep: wait while dispatching the thread's messages ---- */

static void sleep_pumping(DWORD milliseconds)
{
    DWORD start = GetTickCount();
    for (;;)
    {
        MSG msg;
        while (PeekMessageW(&msg, NULL, 0, 0, PM_REMOVE))
        {
            TranslateMessage(&msg);
            DispatchMessageW(&msg);
        }
        DWORD elapsed = GetTickCount() - start;
        if (elapsed >= milliseconds)
        {
            return;
        }
        MsgWaitForMultipleObjects(0, NULL, FALSE, milliseconds - elapsed, QS_ALLINPUT);
    }
}

/* ---- WScript.Arguments ---- */

enum { ID_ITEM = 0, ID_COUNT = 1, ID_LENGTH = 2 };
static const member argument_members[] = {{L"Item", ID_ITEM}, {L"Count", ID_COUNT}, {L"Length", ID_LENGTH}};

static HRESULT STDMETHODCALLTYPE args_QueryInterface(IDispatch *iface, REFIID riid, void **out)
{
    if (IsEqualIID(riid, &IID_IUnknown) || IsEqualIID(riid, &IID_IDispatch))
    {
        *out = iface;
        return S_OK;
    }
    *out = NULL;
    return E_NOINTERFACE;
}

static ULONG STDMETHODCALLTYPE static_AddRef(IDispatch *iface)
{
    return 2;
}

static ULONG STDMETHODCALLTYPE static_Release(IDispatch *iface)
{
    return 1;
}

static HRESULT STDMETHODCALLTYPE no_GetTypeInfoCount(IDispatch *iface, UINT *count)
{
    *count = 0;
    return S_OK;
}

static HRESULT STDMETHODCALLTYPE no_GetTypeInfo(IDispatch *iface, UINT index, LCID lcid, ITypeInfo **info)
{
    return E_NOTIMPL;
}

static HRESULT STDMETHODCALLTYPE args_GetIDsOfNames(IDispatch *iface, REFIID riid, LPOLESTR *names, UINT count, LCID lcid, DISPID *ids)
{
    return find_ids(argument_members, 3, names, count, ids);
}

static HRESULT STDMETHODCALLTYPE args_Invoke(IDispatch *iface, DISPID id, REFIID riid, LCID lcid, WORD flags,
    DISPPARAMS *params, VARIANT *result, EXCEPINFO *info, UINT *arg_error)
{
    if (id == ID_COUNT || id == ID_LENGTH)
    {
        if (result)
        {
            V_VT(result) = VT_I4;
            V_I4(result) = g_argc;
        }
        return S_OK;
    }
    if (id != ID_ITEM || params->cArgs != 1)
    {
        return DISP_E_MEMBERNOTFOUND;
    }
    VARIANT index;
    HRESULT hr = argument_as(params, 0, VT_I4, &index);
    if (FAILED(hr))
    {
        return hr;
    }
    if (V_I4(&index) < 0 || V_I4(&index) >= g_argc)
    {
        set_exception(info, L"Subscript out of range", DISP_E_BADINDEX);
        return DISP_E_EXCEPTION;
    }
    if (result)
    {
        V_VT(result) = VT_BSTR;
        V_BSTR(result) = SysAllocString(g_argv[V_I4(&index)]);
    }
    return S_OK;
}

static const IDispatchVtbl args_vtbl = {
    args_QueryInterface, static_AddRef, static_Release,
    no_GetTypeInfoCount, no_GetTypeInfo, args_GetIDsOfNames, args_Invoke,
};
static IDispatch g_arguments = {&args_vtbl};

/* ---- WScript ---- */

enum { ID_ECHO = 1, ID_ARGUMENTS, ID_QUIT, ID_SLEEP, ID_CONNECT, ID_DISCONNECT, ID_CREATE, ID_NAME, ID_SCRIPTFULLNAME };
static const member wscript_members[] = {
    {L"Echo", ID_ECHO}, {L"Arguments", ID_ARGUMENTS}, {L"Quit", ID_QUIT}, {L"Sleep", ID_SLEEP},
    {L"ConnectObject", ID_CONNECT}, {L"DisconnectObject", ID_DISCONNECT}, {L"CreateObject", ID_CREATE},
    {L"Name", ID_NAME}, {L"ScriptFullName", ID_SCRIPTFULLNAME},
};

static HRESULT STDMETHODCALLTYPE wscript_GetIDsOfNames(IDispatch *iface, REFIID riid, LPOLESTR *names, UINT count, LCID lcid, DISPID *ids)
{
    return find_ids(wscript_members, sizeof(wscript_members) / sizeof(wscript_members[0]), names, count, ids);
}

static HRESULT echo(DISPPARAMS *params)
{
    size_t capacity = 256, used = 0;
    WCHAR *line = malloc(capacity * sizeof(WCHAR));
    line[0] = 0;
    for (UINT i = 0; i < params->cArgs; i++)
    {
        VARIANT text;
        HRESULT hr = argument_as(params, i, VT_BSTR, &text);
        if (FAILED(hr))
        {
            free(line);
            return hr;
        }
        size_t length = SysStringLen(V_BSTR(&text));
        if (used + length + 2 > capacity)
        {
            capacity = (used + length + 2) * 2;
            line = realloc(line, capacity * sizeof(WCHAR));
        }
        if (i > 0)
        {
            line[used++] = L' ';
        }
        memcpy(line + used, V_BSTR(&text), length * sizeof(WCHAR));
        used += length;
        line[used] = 0;
        VariantClear(&text);
    }
    print_line(stdout, line);
    free(line);
    return S_OK;
}

static HRESULT STDMETHODCALLTYPE wscript_Invoke(IDispatch *iface, DISPID id, REFIID riid, LCID lcid, WORD flags,
    DISPPARAMS *params, VARIANT *result, EXCEPINFO *info, UINT *arg_error)
{
    VARIANT value;
    HRESULT hr;
    switch (id)
    {
    case ID_ECHO:
        return echo(params);
    case ID_ARGUMENTS:
        if (params->cArgs == 1)
        {
            return args_Invoke(&g_arguments, ID_ITEM, riid, lcid, flags, params, result, info, arg_error);
        }
        if (result)
        {
            V_VT(result) = VT_DISPATCH;
            V_DISPATCH(result) = &g_arguments;
        }
        return S_OK;
    case ID_NAME:
    case ID_SCRIPTFULLNAME:
        if (result)
        {
            V_VT(result) = VT_BSTR;
            V_BSTR(result) = SysAllocString(id == ID_NAME ? L"Windows Script Host" : g_script_path);
        }
        return S_OK;
    case ID_QUIT:
    {
        int code = 0;
        if (params->cArgs > 0 && SUCCEEDED(argument_as(params, 0, VT_I4, &value)))
        {
            code = V_I4(&value);
        }
        fflush(stdout);
        fflush(stderr);
        ExitProcess(code);
    }
    case ID_SLEEP:
        if (params->cArgs != 1)
        {
            return DISP_E_BADPARAMCOUNT;
        }
        hr = argument_as(params, 0, VT_I4, &value);
        if (FAILED(hr))
        {
            return hr;
        }
        sleep_pumping(V_I4(&value) < 0 ? 0 : (DWORD)V_I4(&value));
        return S_OK;
    case ID_CONNECT:
    case ID_DISCONNECT:
    {
        if (params->cArgs != (id == ID_CONNECT ? 2u : 1u))
        {
            return DISP_E_BADPARAMCOUNT;
        }
        VARIANT *object = argument(params, 0);
        if (V_VT(object) != VT_DISPATCH || !V_DISPATCH(object))
        {
            return DISP_E_TYPEMISMATCH;
        }
        if (id == ID_DISCONNECT)
        {
            return disconnect_object(V_DISPATCH(object));
        }
        hr = argument_as(params, 1, VT_BSTR, &value);
        if (FAILED(hr))
        {
            return hr;
        }
        hr = connect_object(V_DISPATCH(object), V_BSTR(&value));
        VariantClear(&value);
        return hr;
    }
    case ID_CREATE:
    {
        if (params->cArgs < 1 || params->cArgs > 2)
        {
            return DISP_E_BADPARAMCOUNT;
        }
        CLSID clsid;
        IDispatch *object = NULL;
        hr = argument_as(params, 0, VT_BSTR, &value);
        if (FAILED(hr))
        {
            return hr;
        }
        hr = CLSIDFromProgID(V_BSTR(&value), &clsid);
        VariantClear(&value);
        if (SUCCEEDED(hr))
        {
            hr = CoCreateInstance(&clsid, NULL, CLSCTX_INPROC_SERVER | CLSCTX_LOCAL_SERVER, &IID_IDispatch, (void **)&object);
        }
        if (SUCCEEDED(hr) && params->cArgs == 2)
        {
            hr = argument_as(params, 1, VT_BSTR, &value);
            if (SUCCEEDED(hr))
            {
                hr = connect_object(object, V_BSTR(&value));
                VariantClear(&value);
            }
        }
        if (FAILED(hr))
        {
            if (object)
            {
                IDispatch_Release(object);
            }
            return hr;
        }
        if (result)
        {
            V_VT(result) = VT_DISPATCH;
            V_DISPATCH(result) = object;
        }
        else
        {
            IDispatch_Release(object);
        }
        return S_OK;
    }
    }
    return DISP_E_MEMBERNOTFOUND;
}

static const IDispatchVtbl wscript_vtbl = {
    args_QueryInterface, static_AddRef, static_Release,
    no_GetTypeInfoCount, no_GetTypeInfo, wscript_GetIDsOfNames, wscript_Invoke,
};
static IDispatch g_wscript = {&wscript_vtbl};

/* ---- the script site ---- */

static HRESULT STDMETHODCALLTYPE site_QueryInterface(IActiveScriptSite *iface, REFIID riid, void **out)
{
    if (IsEqualIID(riid, &IID_IUnknown) || IsEqualIID(riid, &IID_IActiveScriptSite))
    {
        *out = iface;
        return S_OK;
    }
    *out = NULL;
    return E_NOINTERFACE;
}

static ULONG STDMETHODCALLTYPE site_AddRef(IActiveScriptSite *iface)
{
    return 2;
}

static ULONG STDMETHODCALLTYPE site_Release(IActiveScriptSite *iface)
{
    return 1;
}

static HRESULT STDMETHODCALLTYPE site_GetLCID(IActiveScriptSite *iface, LCID *lcid)
{
    *lcid = MAKELCID(MAKELANGID(LANG_ENGLISH, SUBLANG_ENGLISH_US), SORT_DEFAULT);
    return S_OK;
}

static HRESULT STDMETHODCALLTYPE site_GetItemInfo(IActiveScriptSite *iface, LPCOLESTR name, DWORD mask, IUnknown **item, ITypeInfo **type_info)
{
    if (_wcsicmp(name, L"WScript") != 0)
    {
        return TYPE_E_ELEMENTNOTFOUND;
    }
    if (mask & SCRIPTINFO_ITYPEINFO)
    {
        if (type_info)
        {
            *type_info = NULL;
        }
        if (!(mask & SCRIPTINFO_IUNKNOWN))
        {
            return E_NOTIMPL;
        }
    }
    if (mask & SCRIPTINFO_IUNKNOWN)
    {
        *item = (IUnknown *)&g_wscript;
    }
    return S_OK;
}

static HRESULT STDMETHODCALLTYPE site_GetDocVersionString(IActiveScriptSite *iface, BSTR *version)
{
    return E_NOTIMPL;
}

static HRESULT STDMETHODCALLTYPE site_OnScriptTerminate(IActiveScriptSite *iface, const VARIANT *result, const EXCEPINFO *info)
{
    return S_OK;
}

static HRESULT STDMETHODCALLTYPE site_OnStateChange(IActiveScriptSite *iface, SCRIPTSTATE state)
{
    return S_OK;
}

static HRESULT STDMETHODCALLTYPE site_OnScriptError(IActiveScriptSite *iface, IActiveScriptError *error)
{
    EXCEPINFO info;
    DWORD context;
    ULONG line = 0;
    LONG column = 0;
    memset(&info, 0, sizeof(info));
    IActiveScriptError_GetExceptionInfo(error, &info);
    IActiveScriptError_GetSourcePosition(error, &context, &line, &column);
    if (info.pfnDeferredFillIn)
    {
        info.pfnDeferredFillIn(&info);
    }
    WCHAR text[2048];
    _snwprintf(text, 2048, L"%s(%lu, %ld) %s: %s (0x%08lX)", g_script_path, line + 1, column + 1,
        info.bstrSource ? info.bstrSource : L"Error", info.bstrDescription ? info.bstrDescription : L"",
        (unsigned long)(info.scode ? info.scode : (SCODE)info.wCode));
    text[2047] = 0;
    print_line(stderr, text);
    SysFreeString(info.bstrSource);
    SysFreeString(info.bstrDescription);
    SysFreeString(info.bstrHelpFile);
    g_failed = 1;
    return S_OK;
}

static HRESULT STDMETHODCALLTYPE site_OnEnterScript(IActiveScriptSite *iface)
{
    return S_OK;
}

static HRESULT STDMETHODCALLTYPE site_OnLeaveScript(IActiveScriptSite *iface)
{
    return S_OK;
}

static const IActiveScriptSiteVtbl site_vtbl = {
    site_QueryInterface, site_AddRef, site_Release, site_GetLCID, site_GetItemInfo, site_GetDocVersionString,
    site_OnScriptTerminate, site_OnStateChange, site_OnScriptError, site_OnEnterScript, site_OnLeaveScript,
};
static IActiveScriptSite g_site = {&site_vtbl};

/* ---- main ---- */

static WCHAR *read_script(const WCHAR *path)
{
    HANDLE file = CreateFileW(path, GENERIC_READ, FILE_SHARE_READ, NULL, OPEN_EXISTING, 0, NULL);
    if (file == INVALID_HANDLE_VALUE)
    {
        return NULL;
    }
    DWORD size = GetFileSize(file, NULL), read = 0;
    char *bytes = malloc(size + 1);
    ReadFile(file, bytes, size, &read, NULL);
    CloseHandle(file);
    bytes[read] = 0;
    char *start = bytes;
    if (read >= 3 && (unsigned char)bytes[0] == 0xEF && (unsigned char)bytes[1] == 0xBB && (unsigned char)bytes[2] == 0xBF)
    {
        start += 3;
    }
    int length = MultiByteToWideChar(CP_UTF8, 0, start, -1, NULL, 0);
    WCHAR *text = malloc(length * sizeof(WCHAR));
    MultiByteToWideChar(CP_UTF8, 0, start, -1, text, length);
    free(bytes);
    return text;
}

int wmain(int argc, WCHAR **argv)
{
    if (argc < 2)
    {
        fprintf(stderr, "usage: scripthost script.vbs [arguments...]\n");
        return 2;
    }
    GetFullPathNameW(argv[1], MAX_PATH, g_script_path, NULL);
    g_argc = argc - 2;
    g_argv = argv + 2;

    WCHAR *code = read_script(g_script_path);
    if (!code)
    {
        fprintf(stderr, "scripthost: cannot read %ls\n", g_script_path);
        return 2;
    }

    g_script_thread = GetCurrentThreadId();
    HRESULT hr = CoInitializeEx(NULL, COINIT_APARTMENTTHREADED);
    IActiveScriptParse *parse = NULL;
    if (SUCCEEDED(hr))
    {
        hr = CoCreateInstance(&CLSID_VBScriptEngine, NULL, CLSCTX_INPROC_SERVER, &IID_IActiveScript, (void **)&g_engine);
    }
    if (SUCCEEDED(hr))
    {
        hr = IActiveScript_QueryInterface(g_engine, &IID_IActiveScriptParse, (void **)&parse);
    }
    if (SUCCEEDED(hr))
    {
        hr = parse->lpVtbl->InitNew(parse);
    }
    if (SUCCEEDED(hr))
    {
        hr = IActiveScript_SetScriptSite(g_engine, &g_site);
    }
    if (SUCCEEDED(hr))
    {
        hr = IActiveScript_AddNamedItem(g_engine, L"WScript", SCRIPTITEM_ISVISIBLE);
    }
    if (SUCCEEDED(hr))
    {
        EXCEPINFO info;
        memset(&info, 0, sizeof(info));
        hr = parse->lpVtbl->ParseScriptText(parse, code, NULL, NULL, NULL, 0, 0, SCRIPTTEXT_ISVISIBLE, NULL, &info);
    }
    if (SUCCEEDED(hr))
    {
        hr = IActiveScript_SetScriptState(g_engine, SCRIPTSTATE_CONNECTED);
    }
    if (FAILED(hr) && !g_failed)
    {
        fprintf(stderr, "scripthost: the VBScript engine failed (0x%08lX)\n", (unsigned long)hr);
        g_failed = 1;
    }
    fflush(stdout);
    disconnect_all();
    if (parse)
    {
        parse->lpVtbl->Release(parse);
    }
    if (g_engine)
    {
        IActiveScript_Close(g_engine);
        IActiveScript_Release(g_engine);
    }
    free(code);
    CoUninitialize();
    return g_failed ? 1 : 0;
}
