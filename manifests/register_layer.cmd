@echo off
rem Registers roomsense's implicit OpenXR API layer with the Windows OpenXR loader, which finds implicit
rem layers in HKLM\SOFTWARE\Khronos\OpenXR\1\ApiLayers\Implicit: one DWORD value per layer, named by the
rem full path of its manifest, 0 meaning enabled. Run it from an administrator's prompt:
rem   register_layer.cmd           registers the manifest beside this script
rem   register_layer.cmd /remove   unregisters it
rem DISABLE_XR_APILAYER_ROOMSENSE=1 in an app's environment still turns the layer off for that app.
rem (errorlevel is tested on its own line: Wine's cmd, which CI runs this under, mistakes "|| goto" after a redirection.)
setlocal
set "KEY=HKLM\SOFTWARE\Khronos\OpenXR\1\ApiLayers\Implicit"
set "MANIFEST=%~dp0XR_APILAYER_ROOMSENSE_room_understanding.json"
if not exist "%MANIFEST%" goto missing
if /i "%~1"=="/remove" goto remove
if not "%~1"=="" goto usage
reg add "%KEY%" /v "%MANIFEST%" /t REG_DWORD /d 0 /f >nul 2>&1
if errorlevel 1 goto denied
echo registered %MANIFEST% in %KEY%
exit /b 0

:remove
reg delete "%KEY%" /v "%MANIFEST%" /f >nul 2>&1
if errorlevel 1 goto not_registered
echo unregistered %MANIFEST%
exit /b 0

:missing
echo register_layer: the manifest %MANIFEST% is missing 1>&2
exit /b 1

:denied
echo register_layer: cannot write %KEY%: run it from an administrator's prompt 1>&2
exit /b 1

:not_registered
echo register_layer: %MANIFEST% was not registered 1>&2
exit /b 1

:usage
echo usage: register_layer.cmd [/remove] 1>&2
exit /b 2
