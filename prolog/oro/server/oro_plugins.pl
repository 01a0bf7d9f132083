:- module(oro_plugins,
          [ oro_load_plugins/1,         % +Files
            oro_load_plugin/1,          % +File
            oro_unload_plugin/1,        % +File
            oro_unload_plugins/0,
            oro_plugin/3                % ?File, ?Module, ?Signatures
          ]).
:- use_module(library(error)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(pairs)).
:- use_module(library(debug)).
:- use_module(library(oro/server/oro_methods)).

/** <module> Plugins: RPC methods written in Prolog

A plugin is a Prolog module file that declares RPC methods with the
very hook the built-in methods use, oro_methods:method/4.  Load it
with `--plugin=FILE` (repeatable) on the command line, with
`plugin(File)` options of oro_server_start/2, or with
oro_load_plugin/1.  Its methods are then listed by listMethods,
listSimpleMethods, methods and help, decoded, called and mapped to
ORO errors exactly like the built-in ones.

## Writing a plugin

    :- module(count_instances, []).
    :- use_module(library(oro)).

    oro_methods:method(countInstancesOf(string), taxonomy,
                       "Returns the number of instances of a class.",
                       count_instances_of).

    count_instances_of(ClassName, int(N)) :-
        oro_name_iri(ClassName, Class),
        oro_instances(myself, Class, Instances),
        length(Instances, N).

  - The file must be a module file (`:- module(Name, [])`); it is
    loaded into that module.  library(oro), the whole Prolog API
    (store, reasoner, events), is on the library path.
  - Each method is one fact
    `oro_methods:method(Signature, Category, Help, Implementation)`:
    Signature is Name(Type, ...) with each Type `string`, `set` or
    `list` (`countInstancesOf(string)` is listed as
    `countInstancesOf(String)`); Category (an atom) groups it in
    `help`; Help is a one-line string.
  - Implementation is a predicate of the plugin's module (it is
    module-qualified at load time), called as
    call(Implementation, Arg1, ..., ArgN, Reply): strings for
    `String` parameters, lists of strings for `Set` and `List`.  Reply
    is a value of oro_protocol: `void`, `bool(B)`, `int(N)`,
    `float(X)`, `string(S)`, `list(Values)`, `map(Key-Value pairs)`,
    `raw(Text)`.  context(Goal) gets the connection's context dict
    first: call(Goal, Context, Arg1, ..., ArgN, Reply).
    read_only(Implementation) declares a method that changes nothing
    in the store (see Transactions below).
  - Errors are reported to the client as ORO errors: throw the
    ISO-shaped errors of oro's library (existence_error(class, IRI)
    becomes a NotFoundException...); any other exception, or a
    failure, becomes an OntologyServerException.

## Transactions

A plugin method is one change of the store, as atomic as a built-in
add: the loader declares its Implementation as
transaction(Implementation) (see oro_methods), so it runs under the
store's write lock in one rdf_db transaction (oro_store_write/2, action
method(Name)).  rdf_db transactions nest: every oro_add/2,
oro_remove/2, oro_update/2... the method makes joins that transaction.
So when the method succeeds its changes are committed together and the
event watchers see one change (one event for two oro_add/2 calls);
when it fails or raises, none of them is kept.

The price is the write lock, held for the whole call: other writers
wait for it (readers do not).  A method that changes nothing in the
store should say so:

    oro_methods:method(countInstancesOf(string), taxonomy,
                       "Returns the number of instances of a class.",
                       read_only(count_instances_of)).

read_only(Goal) or read_only(context(Goal)) is called as is, like a
built-in reading method: no lock, no transaction (an oro_add/2 it makes
anyway is its own transaction).  It is *required* for a method that
registers or removes watchers or waits for them (oro_subscribe/7,
oro_register_event/7, oro_unsubscribe/1, oro_clear_events/1,
oro_events_sync/0, oro_reset/0): those take an rdf_db snapshot that
other threads use, or wait for the watcher thread, which may itself
wait for the write lock (it creates agent models); neither may happen
inside a write transaction.  Listing watchers (oro_watchers/2) is fine
either way.

The write lock is taken even by a method that turns out to change
nothing: whether it will change something is only known once it runs,
and the lock must be held from its first read that a change depends
on.

## What loading checks

  - A file that cannot be loaded (missing, not a module file, syntax
    error, an exception or failure in a directive) is reported with
    print_message/2 and unloaded again: none of its methods is
    registered.  So is a file that is loaded already as an ordinary
    Prolog file (a library, a module of oro): unloading it later would
    break its users.
  - A declaration whose name (compared case-insensitively, as the
    dispatcher does) and arity are already declared -- by the built-in
    methods, another plugin or the same file -- is reported and
    dropped; the method declared first wins.  So is a malformed
    declaration.  The rest of the plugin is loaded.
  - An Implementation that is not defined once the file is loaded is
    reported (calls to it will answer an error).

The method table is process-wide: oro_unload_plugin/1 and
oro_unload_plugins/0 remove what plugins declared.
*/

:- dynamic
    plugin/3,                   % Path, Module, Signatures
    plugin_file/1.              % Path: loaded by us (maybe unloaded since)

:- thread_local
    loading/1,                  % Path: oro_load_plugin/1 runs in this thread
    load_problem/1,             % Message: the load failed
    declared/3,                 % Key, Signature, Implementation
    issue/1.                    % Message: reported once the file is loaded

		 /*******************************
		 *            LOADING           *
		 *******************************/

%!  oro_load_plugins(+Files) is det.
%
%   Load each plugin of Files in order with oro_load_plugin/1.

oro_load_plugins(Files) :-
    must_be(list, Files),
    maplist(oro_load_plugin, Files).

%!  oro_load_plugin(+File) is det.
%
%   Load the plugin File and register the methods it declares (see the
%   module documentation).  Problems are reported with print_message/2
%   and never raised: a plugin that cannot be loaded registers
%   nothing, a clashing or malformed declaration is dropped.  Loading a
%   plugin that is loaded already loads it again; a file loaded
%   otherwise (a library, a module of oro) is refused.

oro_load_plugin(File) :-
    must_be(ground, File),
    with_mutex(oro_plugins, load_plugin(File)).

load_plugin(File) :-
    (   absolute_file_name(File, Path,
                           [ file_type(prolog),
                             access(read),
                             file_errors(fail)
                           ])
    ->  (   plugin(Path, _, _)
        ->  unload_plugin(Path),
            load_plugin_file(Path)
        ;   source_file(Path),
            \+ plugin_file(Path)
        ->  print_message(error, oro_plugin(not_a_plugin(Path)))
        ;   load_plugin_file(Path)
        )
    ;   print_message(error, oro_plugin(not_found(File)))
    ).

load_plugin_file(Path) :-
    (   plugin_file(Path)
    ->  true
    ;   assertz(plugin_file(Path))
    ),
    setup_call_cleanup(
        start_loading(Path, HookRef),
        ( catch(load_files(Path, [must_be_module(true), if(true)]),
                Error,
                assertz(load_problem(Error))),
          findall(Problem, load_problem(Problem), Problems),
          findall(Issue, issue(Issue), Issues),
          findall(Sig-Impl, declared(_, Sig, Impl), Methods)
        ),
        end_loading(HookRef)),
    (   Problems == []
    ->  maplist(print_issue, Issues),
        pairs_keys(Methods, Signatures),
        (   module_property(Module, file(Path))
        ->  true
        ;   Module = user
        ),
        assertz(plugin(Path, Module, Signatures)),
        forall(member(Sig-Impl, Methods),
               check_implementation(Path, Sig, Impl)),
        print_message(informational,
                      oro_plugin(loaded(Path, Signatures)))
    ;   catch(unload_file(Path), _, true),
        print_message(error, oro_plugin(load_failed(Path, Problems)))
    ).

%   While the file loads, the thread-local message hook notes the
%   errors the loader prints (syntax errors, exceptions in directives)
%   and failed directives: they make the load fail.

start_loading(Path, HookRef) :-
    retractall(load_problem(_)),
    retractall(declared(_, _, _)),
    retractall(issue(_)),
    asserta(loading(Path)),
    asserta((user:thread_message_hook(Term, Kind, _) :-
                 oro_plugins:note_message(Kind, Term)),
            HookRef).

end_loading(HookRef) :-
    erase(HookRef),
    retractall(loading(_)),
    retractall(load_problem(_)),
    retractall(declared(_, _, _)),
    retractall(issue(_)).

%   note_message(+Kind, +Term) always fails, so the message is printed
%   as usual.

note_message(error, Term) :-
    assertz(load_problem(Term)),
    fail.
note_message(warning, Term) :-
    Term = goal_failed(directive, _),
    assertz(load_problem(Term)),
    fail.

print_issue(Issue) :-
    print_message(warning, oro_plugin(Issue)).

%   check_implementation(+Path, +Signature, +Implementation): warn if
%   the predicate Implementation calls is not defined.

check_implementation(Path, Sig, Impl0) :-
    functor(Sig, _, Arity),
    (   Impl0 = transaction(Impl)
    ->  true
    ;   Impl = Impl0
    ),
    (   Impl = context(Goal)
    ->  Extra is Arity + 2
    ;   Goal = Impl,
        Extra is Arity + 1
    ),
    strip_module(Goal, M, Plain),
    functor(Plain, Name, A0),
    A is A0 + Extra,
    functor(Head, Name, A),
    (   predicate_property(M:Head, defined)
    ->  true
    ;   print_message(warning,
                      oro_plugin(undefined(Path, Sig, M:Name/A)))
    ).

		 /*******************************
		 *          UNLOADING           *
		 *******************************/

%!  oro_unload_plugin(+File) is det.
%
%   Unload the plugin File: its methods leave the method table.  Does
%   nothing if File is not a loaded plugin.

oro_unload_plugin(File) :-
    must_be(ground, File),
    (   absolute_file_name(File, Path,
                           [ file_type(prolog),
                             access(read),
                             file_errors(fail)
                           ])
    ->  with_mutex(oro_plugins, unload_plugin(Path))
    ;   true
    ).

%!  oro_unload_plugins is det.
%
%   Unload every plugin: the method table is the built-in one again.

oro_unload_plugins :-
    with_mutex(oro_plugins,
               forall(plugin(Path, _, _),
                      unload_plugin(Path))).

unload_plugin(Path) :-
    (   retract(plugin(Path, _, _))
    ->  unload_file(Path),
        debug(oro(plugins), 'Unloaded plugin ~w', [Path])
    ;   true
    ).

%!  oro_plugin(?File, ?Module, ?Signatures) is nondet.
%
%   File (an absolute path), loaded into Module, is a plugin that
%   registered the methods Signatures.

oro_plugin(File, Module, Signatures) :-
    plugin(File, Module, Signatures).

		 /*******************************
		 *         DECLARATIONS         *
		 *******************************/

%   While a plugin loads (in this thread), each declaration
%   oro_methods:method(Signature, Category, Help, Implementation) of
%   its files is checked: a malformed or clashing one is dropped (and
%   reported once the file is loaded); a good one gets its
%   Implementation qualified with the module it is declared in.

:- multifile user:term_expansion/2.
:- dynamic user:term_expansion/2.

user:term_expansion(Term, Expanded) :-
    loading(_),
    declaration(Term),
    oro_plugins:expand_declaration(Term, Expanded).

declaration(oro_methods:method(_, _, _, _)).
declaration((oro_methods:method(_, _, _, _) :- _)).

expand_declaration(Term, Expanded) :-
    prolog_load_context(source, File),
    prolog_load_context(module, Module),
    (   Term = (_ :- _)
    ->  Issue = bad_declaration(File, Term, not_a_fact)
    ;   Term = oro_methods:method(Sig, Category, Help0, Impl0),
        valid_declaration(Sig, Category, Help0, Impl0, Why)
    ->  (   nonvar(Why)
        ->  Issue = bad_declaration(File, Term, Why)
        ;   method_key(Sig, Key),
            clash(Key, File, Existing, Owner)
        ->  Issue = clash(File, Sig, Existing, Owner)
        ;   text_to_string(Help0, Help),
            qualify(Impl0, Module, Impl),
            method_key(Sig, Key),
            assertz(declared(Key, Sig, Impl)),
            Expanded = oro_methods:method(Sig, Category, Help, Impl)
        )
    ;   Issue = bad_declaration(File, Term, malformed)
    ),
    (   var(Issue)
    ->  true
    ;   assertz(issue(Issue)),
        Expanded = []
    ).

%   valid_declaration(+Sig, +Category, +Help, +Impl, -Why): Why is left
%   unbound if the declaration is well-formed.

valid_declaration(Sig, _, _, _, Why) :-
    \+ ( callable(Sig),
         Sig =.. [_|Types],
         maplist(param_type, Types)
       ),
    !,
    Why = signature(Sig).
valid_declaration(_, Category, _, _, Why) :-
    \+ atom(Category),
    !,
    Why = category(Category).
valid_declaration(_, _, Help, _, Why) :-
    \+ text(Help),
    !,
    Why = help(Help).
valid_declaration(_, _, _, Impl, Why) :-
    \+ implementation(Impl),
    !,
    Why = implementation(Impl).
valid_declaration(_, _, _, _, _).

param_type(Type) :-
    atom(Type),
    memberchk(Type, [string, set, list]).

text(Text) :-
    (   string(Text)
    ->  true
    ;   atom(Text)
    ).

%   An Implementation is Core, transaction(Core) or read_only(Core),
%   Core being Goal or context(Goal).

implementation(read_only(Core)) :-
    !,
    core_implementation(Core).
implementation(transaction(Core)) :-
    !,
    core_implementation(Core).
implementation(Core) :-
    core_implementation(Core).

core_implementation(context(Goal)) :-
    !,
    callable(Goal).
core_implementation(Goal) :-
    callable(Goal).

%   qualify(+Impl0, +Module, -Impl): the Implementation the method
%   table gets: its goal qualified with Module, and called in a store
%   transaction unless declared read_only(Core).

qualify(read_only(Core0), Module, Core) :-
    !,
    qualify_core(Core0, Module, Core).
qualify(transaction(Core0), Module, transaction(Core)) :-
    !,
    qualify_core(Core0, Module, Core).
qualify(Core0, Module, transaction(Core)) :-
    qualify_core(Core0, Module, Core).

qualify_core(context(Goal), Module, context(Qualified)) :-
    !,
    qualify_goal(Goal, Module, Qualified).
qualify_core(Goal, Module, Qualified) :-
    qualify_goal(Goal, Module, Qualified).

qualify_goal(Goal, _, Goal) :-
    Goal = _:_,
    !.
qualify_goal(Goal, Module, Module:Goal).

%   The dispatcher finds a method by its name, case-insensitively, and
%   its arity.

method_key(Sig, Lower/Arity) :-
    functor(Sig, Name, Arity),
    downcase_atom(Name, Lower).

%   clash(+Key, +File, -Existing, -Owner): a method with Key is
%   declared already: by this load (in File or a file it loaded), or by
%   a file other than File (when File is reloaded, its own previous
%   clauses do not count).

clash(Key, _, Existing, Owner) :-
    declared(Key, Existing, _),
    !,
    Owner = this_plugin.
clash(Key, File, Existing, Owner) :-
    clause(oro_methods:method(Existing, _, _, _), true, Ref),
    method_key(Existing, Key),
    (   clause_property(Ref, source(Source))
    ->  Source \== File
    ;   Source = unknown
    ),
    !,
    owner(Source, Owner).

owner(Source, Owner) :-
    (   plugin(Source, _, _)
    ->  Owner = plugin(Source)
    ;   built_in_file(Source)
    ->  Owner = built_in
    ;   Owner = file(Source)
    ).

%   The built-in methods are declared in server/ (oro_methods.pl and
%   its companions).

built_in_file(Source) :-
    atom(Source),
    module_property(oro_methods, file(MethodsFile)),
    file_directory_name(MethodsFile, Dir),
    file_directory_name(Source, Dir).

		 /*******************************
		 *           MESSAGES           *
		 *******************************/

:- multifile prolog:message//1.

prolog:message(oro_plugin(Message)) -->
    message(Message).

message(loaded(File, Signatures)) -->
    [ 'oro: plugin ~w loaded'-[File] ],
    loaded_methods(Signatures).
message(not_found(File)) -->
    [ 'oro: plugin ~w not loaded: no such readable Prolog file'-[File] ].
message(not_a_plugin(File)) -->
    [ 'oro: plugin ~w not loaded: it is loaded already, as an ordinary \c
       Prolog file'-[File] ].
message(load_failed(File, Problems)) -->
    [ 'oro: plugin ~w not loaded (none of its methods is available):'-[File] ],
    problems(Problems).
message(clash(File, Sig, Existing, Owner)) -->
    { oro_simple_signature(Sig, S),
      oro_simple_signature(Existing, E)
    },
    [ 'oro: plugin ~w: method ~w not added: ~w is already declared by '-
      [File, S, E] ],
    owner(Owner).
message(bad_declaration(File, Term, Why)) -->
    [ 'oro: plugin ~w: declaration ~q ignored: '-[File, Term] ],
    why(Why).
message(undefined(File, Sig, PI)) -->
    { oro_simple_signature(Sig, S) },
    [ 'oro: plugin ~w: method ~w: its implementation ~q is not defined'-
      [File, S, PI] ].

loaded_methods([]) -->
    !,
    [ ' (it declares no method)' ].
loaded_methods(Signatures) -->
    { maplist(oro_simple_signature, Signatures, Texts),
      atomic_list_concat(Texts, ', ', List)
    },
    [ ': ~w'-[List] ].

problems([]) -->
    [].
problems([H|T]) -->
    [ nl, '    ' ],
    problem(H),
    problems(T).

problem(error(domain_error(module_header, _), _)) -->
    !,
    [ 'it is not a module file: it must start with :- module(Name, []).' ].
problem(Term) -->
    { catch('$messages':translate_message(Term, Lines, []), _, fail),
      exclude(==(nl), Lines, OneLine)
    },
    !,
    OneLine.
problem(Term) -->
    [ '~q'-[Term] ].

owner(built_in) -->
    [ 'a built-in method' ].
owner(this_plugin) -->
    [ 'the same plugin' ].
owner(plugin(File)) -->
    [ 'the plugin ~w'-[File] ].
owner(file(File)) -->
    [ '~w'-[File] ].

why(not_a_fact) -->
    [ 'a method is declared by a fact, not a rule' ].
why(malformed) -->
    [ 'expected method(Signature, Category, Help, Implementation)' ].
why(signature(Sig)) -->
    [ 'the signature ~q is not Name(Type, ...) with each Type string, \c
       set or list'-[Sig] ].
why(category(Category)) -->
    [ 'the category ~q is not an atom'-[Category] ].
why(help(Help)) -->
    [ 'the help text ~q is not a string'-[Help] ].
why(implementation(Impl)) -->
    [ 'the implementation ~q is not callable'-[Impl] ].
