<#
.SYNOPSIS
    Installs (or removes) OmronHostLink.Gateway as a Windows service.

.DESCRIPTION
    Run from an elevated PowerShell (Windows PowerShell 5.1 or PowerShell 7) on the published gateway:

        dotnet publish src\OmronHostLink.Gateway -c Release -r win-x64 --self-contained -o C:\Services\OmronHostLink.Gateway
        C:\Services\OmronHostLink.Gateway\deploy\install-service.ps1 -Start

    The service:
      - starts automatically, delayed (start= delayed-auto), after the boot-critical services;
      - runs as its own virtual account NT SERVICE\<Name> (no password; it can open COM ports and read the folder);
      - is restarted by the service control manager after 5 s, 5 s and then 60 s when it fails, including when it stops
        with a non-zero exit code (an invalid configuration exits with 2: restarts cannot fix that, the event log says
        what is wrong);
      - logs warnings and errors to the Application event log under the source <Name>;
      - may write its state folder %ProgramData%\OmronHostLink.Gateway (created here; the durable MQTT queue and the
        count of unsent messages live there).
    The gateway reports its state to the service control manager (Microsoft.Extensions.Hosting.WindowsServices), a
    service stop is a graceful shutdown, and appsettings.json is read from the installation folder.

.PARAMETER Name
    Service name, also the event log source. Default: OmronHostLink.Gateway (the name the gateway reports under).

.PARAMETER InstallDir
    Folder holding OmronHostLink.Gateway.exe. Default: the folder above this script (publish puts deploy\ there).

.PARAMETER Start
    Start the service once installed.

.PARAMETER Uninstall
    Stop and delete the service and its event log source instead.

.EXAMPLE
    .\install-service.ps1 -Start

.EXAMPLE
    .\install-service.ps1 -Uninstall
#>
#Requires -RunAsAdministrator
[CmdletBinding()]
param(
    [string] $Name = 'OmronHostLink.Gateway',
    [string] $InstallDir = (Split-Path -Parent $PSScriptRoot),
    [switch] $Start,
    [switch] $Uninstall
)

$ErrorActionPreference = 'Stop'

function Invoke-Sc {
    # sc.exe takes "option=" and its value as separate arguments.
    & sc.exe @args | Out-Host
    if ($LASTEXITCODE -ne 0) {
        throw "sc.exe $($args -join ' ') failed with exit code $LASTEXITCODE."
    }
}

$existing = Get-Service -Name $Name -ErrorAction SilentlyContinue

if ($Uninstall) {
    if ($existing) {
        if ($existing.Status -ne 'Stopped') {
            Stop-Service -Name $Name
        }
        Invoke-Sc delete $Name
    }
    if ([System.Diagnostics.EventLog]::SourceExists($Name)) {
        [System.Diagnostics.EventLog]::DeleteEventSource($Name)
    }
    Write-Host "Service $Name removed."
    return
}

$exe = Join-Path $InstallDir 'OmronHostLink.Gateway.exe'
if (-not (Test-Path -LiteralPath $exe -PathType Leaf)) {
    throw "$exe not found. Publish the gateway first (dotnet publish src\OmronHostLink.Gateway -c Release -r win-x64 -o <folder>) and pass that folder as -InstallDir."
}
if ($existing) {
    throw "A service named $Name exists already. Remove it first with: $PSCommandPath -Uninstall"
}

# New-Service passes the path to the service control manager as it is, so a path with spaces keeps its quotes
# (sc.exe create binPath= needs them escaped differently by each PowerShell version).
New-Service -Name $Name `
    -BinaryPathName "`"$exe`"" `
    -DisplayName 'OmronHostLink gateway (Host Link to MQTT)' `
    -Description 'Polls Omron PLCs over Host Link and publishes the values over MQTT. See docs/deployment.md.' `
    -StartupType Automatic | Out-Null

Invoke-Sc config $Name start= delayed-auto obj= "NT SERVICE\$Name"
# Restart after 5 s, 5 s, then every 60 s; the failure count resets after a day without failure.
Invoke-Sc failure $Name reset= 86400 actions= restart/5000/restart/5000/restart/60000
# Count a stop with a non-zero exit code as a failure too, not only a crash.
Invoke-Sc failureflag $Name 1

# The event log source must exist before the service's account (which may not create one) writes to it.
if (-not [System.Diagnostics.EventLog]::SourceExists($Name)) {
    [System.Diagnostics.EventLog]::CreateEventSource($Name, 'Application')
}

# The gateway's state (the count of unsent MQTT messages, the durable queue) lives in %ProgramData%\OmronHostLink.Gateway
# unless Mqtt:StateDirectory says otherwise; only the service's account (and administrators) may change it.
$state = Join-Path $env:ProgramData 'OmronHostLink.Gateway'
New-Item -ItemType Directory -Force -Path $state | Out-Null
& icacls.exe $state /grant "NT SERVICE\${Name}:(OI)(CI)M" | Out-Host
if ($LASTEXITCODE -ne 0) {
    throw "icacls.exe could not give NT SERVICE\$Name write access to $state (exit code $LASTEXITCODE)."
}

Write-Host "Service $Name installed: $exe (delayed automatic start, account NT SERVICE\$Name)."
if ($Start) {
    Start-Service -Name $Name
    Get-Service -Name $Name | Format-Table -AutoSize Name, Status, StartType | Out-Host
}
