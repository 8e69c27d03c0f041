@echo off
rem Registers the OmronHostLink COM server (ProgId OmronHostLink.Plc and its type library) for every bitness in this
rem folder: x64\ for 64-bit programs (64-bit Office, 64-bit cscript), x86\ for 32-bit ones (VB6, 32-bit Office,
rem C:\Windows\SysWOW64\cscript.exe). Run it from an elevated command prompt; it needs the .NET 10 runtime of the same
rem bitness (https://dotnet.microsoft.com/download/dotnet/10.0: ".NET Runtime", x64 and/or x86).
setlocal
set "here=%~dp0"
set "status=0"

if exist "%here%x64\OmronHostLink.Com.comhost.dll" call :register x64 "%SystemRoot%\System32\regsvr32.exe" "%ProgramW6432%\dotnet"
if exist "%here%x86\OmronHostLink.Com.comhost.dll" (
  if exist "%SystemRoot%\SysWOW64\regsvr32.exe" (
    call :register x86 "%SystemRoot%\SysWOW64\regsvr32.exe" "%ProgramFiles(x86)%\dotnet"
  ) else (
    call :register x86 "%SystemRoot%\System32\regsvr32.exe" "%ProgramFiles%\dotnet"
  )
)
exit /b %status%

:register
set "bits=%~1"
set "regsvr=%~2"
set "dotnet=%~3"
dir /b /ad "%dotnet%\shared\Microsoft.NETCore.App\10.*" >nul 2>&1
if errorlevel 1 (
  echo register.cmd: the %bits% .NET 10 runtime is not in "%dotnet%"; install ".NET Runtime 10" for %bits% first.
  set "status=3"
  goto :eof
)
"%regsvr%" /s "%here%%bits%\OmronHostLink.Com.comhost.dll"
if errorlevel 1 (
  echo register.cmd: regsvr32 could not register %here%%bits%\OmronHostLink.Com.comhost.dll: run this script as administrator ^(regsvr32 writes to HKEY_LOCAL_MACHINE^); without /s regsvr32 says why.
  set "status=4"
  goto :eof
)
echo Registered OmronHostLink.Plc ^(%bits%^): %here%%bits%\OmronHostLink.Com.comhost.dll
goto :eof
