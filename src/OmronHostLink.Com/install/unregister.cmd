@echo off
rem Removes what register.cmd registered (the class, its ProgId and the type library) for each bitness in this folder.
rem Run it from an elevated command prompt before deleting or moving the folder.
setlocal
set "here=%~dp0"
set "status=0"
if exist "%here%x64\OmronHostLink.Com.comhost.dll" (
  "%SystemRoot%\System32\regsvr32.exe" /s /u "%here%x64\OmronHostLink.Com.comhost.dll" || set "status=4"
)
if exist "%here%x86\OmronHostLink.Com.comhost.dll" (
  if exist "%SystemRoot%\SysWOW64\regsvr32.exe" (
    "%SystemRoot%\SysWOW64\regsvr32.exe" /s /u "%here%x86\OmronHostLink.Com.comhost.dll" || set "status=4"
  ) else (
    "%SystemRoot%\System32\regsvr32.exe" /s /u "%here%x86\OmronHostLink.Com.comhost.dll" || set "status=4"
  )
)
if "%status%"=="0" echo Unregistered OmronHostLink.Plc.
exit /b %status%
