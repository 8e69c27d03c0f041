/*
 * tlbcheck: what a VB6 or VBA project sees of the COM server, run under Wine by the tests.
 *
 *   tlbcheck.exe dump           the registered type library, read back with LoadRegTypeLib as VBA's References does:
 *                               one line per type and member (name, DISPID, vtable offset, types), for the tests to
 *                               compare with the .NET interfaces.
 *   tlbcheck.exe call HOST:PORT early binding as a VB6 program compiled against the library: OmronHostLink.Plc created
 *                               by its CLSID and called through the IPlc and IPlcStatus vtables the IDL declares
 *                               (the header widl generates from it), errors read through IErrorInfo.
 *
 * Exit code 0 on success; otherwise the failing HRESULT is printed and the exit code is 1.
 */
#define COBJMACROS
#define CINTERFACE
#define CONST_VTABLE
#include <windows.h>
#include <initguid.h>
#include <ole2.h>
#include <oleauto.h>
#include <stdio.h>
#include <wchar.h>
#include "OmronHostLink.Com.h"

static const char *vt_name(VARTYPE vt)
{
    switch (vt & VT_TYPEMASK)
    {
    case VT_I2: return "I2";
    case VT_I4: return "I4";
    case VT_R4: return "R4";
    case VT_R8: return "R8";
    case VT_BSTR: return "BSTR";
    case VT_DISPATCH: return "DISPATCH";
    case VT_BOOL: return "BOOL";
    case VT_VARIANT: return "VARIANT";
    case VT_UNKNOWN: return "UNKNOWN";
    case VT_VOID: return "VOID";
    case VT_HRESULT: return "HRESULT";
    case VT_PTR: return "PTR";
    case VT_USERDEFINED: return "USERDEFINED";
    default: return "OTHER";
    }
}

/* A parameter's or a result's type: PTR(I4), PTR(PTR(USERDEFINED IPlcStatus)). */
static void describe_type(ITypeInfo *info, const TYPEDESC *type, char *out, size_t size)
{
    if (type->vt == VT_PTR)
    {
        char inner[200];
        describe_type(info, type->lptdesc, inner, sizeof(inner));
        snprintf(out, size, "PTR(%s)", inner);
    }
    else if (type->vt == VT_USERDEFINED)
    {
        ITypeInfo *ref = NULL;
        BSTR name = NULL;
        if (SUCCEEDED(ITypeInfo_GetRefTypeInfo(info, type->hreftype, &ref)))
        {
            ITypeInfo_GetDocumentation(ref, MEMBERID_NIL, &name, NULL, NULL, NULL);
            ITypeInfo_Release(ref);
        }
        snprintf(out, size, "USERDEFINED %ls", name ? name : L"?");
        SysFreeString(name);
    }
    else
    {
        snprintf(out, size, "%s", vt_name(type->vt));
    }
}

static const char *kind_name(TYPEKIND kind)
{
    switch (kind)
    {
    case TKIND_ENUM: return "enum";
    case TKIND_INTERFACE: return "interface";
    case TKIND_DISPATCH: return "dispatch";
    case TKIND_COCLASS: return "coclass";
    default: return "other";
    }
}

static const char *invoke_name(INVOKEKIND kind)
{
    switch (kind)
    {
    case INVOKE_PROPERTYGET: return "propget";
    case INVOKE_PROPERTYPUT: return "propput";
    case INVOKE_PROPERTYPUTREF: return "propputref";
    default: return "method";
    }
}

static void dump_type(ITypeInfo *info)
{
    TYPEATTR *attr;
    BSTR name = NULL;
    WCHAR guid[64];
    ITypeInfo_GetTypeAttr(info, &attr);
    ITypeInfo_GetDocumentation(info, MEMBERID_NIL, &name, NULL, NULL, NULL);
    StringFromGUID2(&attr->guid, guid, 64);
    printf("type %s %ls %ls flags=%u\n", kind_name(attr->typekind), name, guid, attr->wTypeFlags);
    SysFreeString(name);

    for (UINT i = 0; i < attr->cVars; i++)
    {
        VARDESC *var;
        ITypeInfo_GetVarDesc(info, i, &var);
        ITypeInfo_GetDocumentation(info, var->memid, &name, NULL, NULL, NULL);
        if (var->varkind == VAR_CONST && var->lpvarValue)
        {
            VARIANT value;
            VariantInit(&value);
            VariantChangeType(&value, var->lpvarValue, 0, VT_I4);
            printf("  const %ls = %ld\n", name, (long)V_I4(&value));
        }
        SysFreeString(name);
        ITypeInfo_ReleaseVarDesc(info, var);
    }

    for (UINT i = 0; i < attr->cFuncs; i++)
    {
        FUNCDESC *func;
        BSTR names[32];
        UINT count = 0;
        char type[256];
        ITypeInfo_GetFuncDesc(info, i, &func);
        ITypeInfo_GetNames(info, func->memid, names, 32, &count);
        describe_type(info, &func->elemdescFunc.tdesc, type, sizeof(type));
        printf("  func %ls id=%ld %s vft=%d ret=%s params=", names[0], (long)func->memid, invoke_name(func->invkind), func->oVft, type);
        for (SHORT p = 0; p < func->cParams; p++)
        {
            const PARAMDESC *param = &func->lprgelemdescParam[p].paramdesc;
            describe_type(info, &func->lprgelemdescParam[p].tdesc, type, sizeof(type));
            printf("%s%s%s%s%s", p ? "," : "", type,
                param->wParamFlags & PARAMFLAG_FOUT ? "[out]" : "",
                param->wParamFlags & PARAMFLAG_FRETVAL ? "[retval]" : "",
                param->wParamFlags & PARAMFLAG_FOPT ? "[optional]" : "");
        }
        printf("\n");
        for (UINT n = 0; n < count; n++)
        {
            SysFreeString(names[n]);
        }
        ITypeInfo_ReleaseFuncDesc(info, func);
    }

    for (UINT i = 0; i < attr->cImplTypes; i++)
    {
        HREFTYPE ref;
        ITypeInfo *impl;
        INT flags = 0;
        ITypeInfo_GetRefTypeOfImplType(info, i, &ref);
        ITypeInfo_GetImplTypeFlags(info, i, &flags);
        if (SUCCEEDED(ITypeInfo_GetRefTypeInfo(info, ref, &impl)))
        {
            ITypeInfo_GetDocumentation(impl, MEMBERID_NIL, &name, NULL, NULL, NULL);
            printf("  implements %ls%s%s\n", name, flags & IMPLTYPEFLAG_FDEFAULT ? " default" : "", flags & IMPLTYPEFLAG_FSOURCE ? " source" : "");
            SysFreeString(name);
            ITypeInfo_Release(impl);
        }
    }
    ITypeInfo_ReleaseTypeAttr(info, attr);
}

static int dump(void)
{
    ITypeLib *library;
    TLIBATTR *attr;
    BSTR path = NULL, name = NULL;
    HRESULT hr = LoadRegTypeLib(&LIBID_OmronHostLink, 1, 0, 0, &library);
    if (FAILED(hr))
    {
        printf("error LoadRegTypeLib 0x%08lX: the type library is not registered\n", (unsigned long)hr);
        return 1;
    }
    ITypeLib_GetLibAttr(library, &attr);
    QueryPathOfRegTypeLib(&LIBID_OmronHostLink, 1, 0, 0, &path);
    ITypeLib_GetDocumentation(library, MEMBERID_NIL, &name, NULL, NULL, NULL);
    printf("library %ls %d.%d syskind=%d path=%ls\n", name, attr->wMajorVerNum, attr->wMinorVerNum, attr->syskind, path);
    ITypeLib_ReleaseTLibAttr(library, attr);
    SysFreeString(path);
    SysFreeString(name);
    for (UINT i = 0; i < ITypeLib_GetTypeInfoCount(library); i++)
    {
        ITypeInfo *info;
        ITypeLib_GetTypeInfo(library, i, &info);
        dump_type(info);
        /* A dual interface's vtable half: its functions with their offsets. */
        TYPEATTR *type;
        ITypeInfo_GetTypeAttr(info, &type);
        if (type->typekind == TKIND_DISPATCH && (type->wTypeFlags & TYPEFLAG_FDUAL))
        {
            HREFTYPE ref;
            ITypeInfo *vtable;
            if (SUCCEEDED(ITypeInfo_GetRefTypeOfImplType(info, -1, &ref)) && SUCCEEDED(ITypeInfo_GetRefTypeInfo(info, ref, &vtable)))
            {
                dump_type(vtable);
                ITypeInfo_Release(vtable);
            }
        }
        ITypeInfo_ReleaseTypeAttr(info, type);
        ITypeInfo_Release(info);
    }
    ITypeLib_Release(library);
    return 0;
}

/* A failed call: its HRESULT and the description from IErrorInfo, as VB's Err object gets them. */
static int failed(const char *what, HRESULT hr)
{
    IErrorInfo *error = NULL;
    BSTR description = NULL;
    if (GetErrorInfo(0, &error) == S_OK)
    {
        IErrorInfo_GetDescription(error, &description);
        IErrorInfo_Release(error);
    }
    printf("%s: error 0x%08lX %ls\n", what, (unsigned long)hr, description ? description : L"");
    SysFreeString(description);
    return (int)hr;
}

static int call(const WCHAR *endpoint)
{
    IPlc *plc = NULL;
    HRESULT hr = CoCreateInstance(&CLSID_Plc, NULL, CLSCTX_INPROC_SERVER, &IID_IPlc, (void **)&plc);
    if (FAILED(hr))
    {
        printf("CoCreateInstance: error 0x%08lX\n", (unsigned long)hr);
        return 1;
    }
    WCHAR connection[256];
    _snwprintf(connection, 256, L"tcp://%s", endpoint);
    BSTR text = SysAllocString(connection);
    hr = IPlc_Open(plc, text);
    SysFreeString(text);
    if (FAILED(hr))
    {
        failed("Open", hr);
        return 1;
    }
    printf("bits %d\n", (int)(sizeof(void *) * 8));

    BSTR address = SysAllocString(L"D100");
    LONG word = -1;
    hr = IPlc_ReadWord(plc, address, &word);
    printf("ReadWord D100: %s %ld\n", SUCCEEDED(hr) ? "ok" : "failed", (long)word);

    BSTR real_address = SysAllocString(L"D300");
    float real = 0;
    hr = IPlc_ReadReal(plc, real_address, &real);
    printf("ReadReal D300: %s %g\n", SUCCEEDED(hr) ? "ok" : "failed", (double)real);

    BSTR write_address = SysAllocString(L"D200");
    hr = IPlc_WriteWord(plc, write_address, 4321);
    if (FAILED(hr))
    {
        failed("WriteWord D200", hr);
    }
    else
    {
        printf("WriteWord D200: ok\n");
    }

    IPlcStatus *status = NULL;
    hr = IPlc_ReadStatus(plc, &status);
    if (SUCCEEDED(hr))
    {
        BSTR mode = NULL;
        LONG status_word = 0;
        IPlcStatus_get_Mode(status, &mode);
        IPlcStatus_get_StatusWord(status, &status_word);
        printf("ReadStatus: ok %ls %ld\n", mode, (long)status_word);
        SysFreeString(mode);
        IPlcStatus_Release(status);
    }
    else
    {
        failed("ReadStatus", hr);
    }

    VARIANT_BOOL open = VARIANT_FALSE;
    IPlc_get_IsOpen(plc, &open);
    printf("IsOpen: %s\n", open ? "True" : "False");
    IPlc_Close(plc);
    IPlc_Release(plc);
    SysFreeString(address);
    SysFreeString(real_address);
    SysFreeString(write_address);
    return 0;
}

int wmain(int argc, WCHAR **argv)
{
    int result = 2;
    CoInitializeEx(NULL, COINIT_APARTMENTTHREADED);
    if (argc == 2 && wcscmp(argv[1], L"dump") == 0)
    {
        result = dump();
    }
    else if (argc == 3 && wcscmp(argv[1], L"call") == 0)
    {
        result = call(argv[2]);
    }
    else
    {
        fprintf(stderr, "usage: tlbcheck dump | tlbcheck call HOST:PORT\n");
    }
    fflush(stdout);
    CoUninitialize();
    return result;
}
