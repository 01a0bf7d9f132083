:- module(oro_server_script, []).
:- prolog_load_context(directory, Dir),
   file_directory_name(Dir, Home),
   directory_file_path(Home, prolog, Lib),
   (   user:file_search_path(library, Lib)
   ->  true
   ;   asserta(user:file_search_path(library, Lib))
   ).
:- reexport(library(oro_server)).
:- use_module(library(lists), [member/2]).

/** <module> The command that starts the ORO socket server

    swipl server/oro_server.pl [option ...]

(`--help` lists the options.)  The server is library(oro_server)
(prolog/oro_server.pl); this script runs oro_server_main/0 when swipl
is started with it, and, loaded as a module, gives the library's
predicates, so `use_module('server/oro_server')` still works.

swipl takes the arguments right after a script whose names end in
`.pl` (`--plugin=examples/plugins/count_instances.pl`) for more files
to load.  While it loads them, the prolog_load_file/2 hook below takes
each argument of the command line for loaded already, so none is
loaded as Prolog and oro_server_main/0 reads them all
(oro_server_arguments/1): the options work in any order, whatever
their file names.
*/

:- prolog_load_context(file, File),
   (   current_prolog_flag(associated_file, File)
   ->  initialization(oro_server_main, main),
       asserta((user:prolog_load_file(user:Argument, _) :-
                   oro_server_script:command_line_argument(Argument)))
   ;   true
   ).

%   command_line_argument(+Argument): Argument is one of the arguments
%   given to the server on the command line.

command_line_argument(Argument) :-
    atom(Argument),
    oro_server_arguments(Arguments),
    member(Argument, Arguments),
    !.
