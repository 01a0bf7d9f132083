:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(pairs)).
:- use_module(library(aggregate)).
:- use_module(library(error)).
:- use_module(library(process)).
:- use_module(library(filesex)).
:- use_module(library(readutil)).
:- use_module(library(oro/server/oro_plugins)).
:- use_module(library(oro/oro_persist), [oro_persist_directory/1]).
:- use_module(library(oro), [oro_close/0]).

/*  Tests of plugins (prolog/oro/server/oro_plugins.pl), over real sockets on
    127.0.0.1: loading with plugin(File) options of oro_server_start/2,
    listing in listMethods, listSimpleMethods, methods and help,
    calling (parameters, context, transactions), a method as one store
    transaction (all its changes or none, one event, one commit), the
    events API used in-process, run-time errors, clashes with built-in
    methods, files that cannot be loaded, and the real command line
    with --plugin (a missing file, two plugins).

    The method table is process-wide: every unit unloads its plugins in
    its cleanup (oro_unload_plugins/0), so no plugin leaks into the
    other test files.  The messages plugins cause while a unit starts
    its server are recorded (plg_message/2) instead of printed.

    Run: cd /work/main && swipl -g run_tests -t halt test/test_plugins.pl
*/

:- dynamic
    capturing_messages/1,                    % Thread
    plg_message/2.                      % Kind, Message


                 /*******************************
                 *     SERVER AND MESSAGES      *
                 *******************************/

%   While capturing_messages(Thread) holds, the messages printed by Thread
%   (the plugin loader's and the loader's own) are kept, not printed:
%   oro_plugin(Message) ones in plg_message/2.

:- multifile user:message_hook/3.
:- dynamic user:message_hook/3.

user:message_hook(Term, Kind, _) :-
    thread_self(Me),
    capturing_messages(Me),
    memberchk(Kind, [error, warning, informational]),
    (   Term = oro_plugin(Message)
    ->  assertz(plg_message(Kind, Message))
    ;   true
    ).

%   plg_start(+Plugins): start a server on the test ontology with the
%   plugins Plugins (files under test/fixtures/plugins/, or paths
%   relative to the checkout), recording the messages.

plg_start(Plugins) :-
    plg_start(Plugins, []).

%   plg_start(+Plugins, +Options): the same, with more options of
%   oro_server_start/2.

plg_start(Plugins, Options) :-
    plg_stop,
    retractall(plg_message(_, _)),
    test_fixture('testsuite.ttl', Ontology),
    maplist(plg_plugin_path, Plugins, Files),
    findall(plugin(F), member(F, Files), PluginOptions),
    append(PluginOptions, Options, AllOptions),
    thread_self(Me),
    setup_call_cleanup(
        assertz(capturing_messages(Me)),
        test_server_start([ commonsense(false),
                            ontology(Ontology)
                          | AllOptions
                          ]),
        retractall(capturing_messages(Me))).

plg_stop :-
    test_server_stop,
    oro_unload_plugins.

plg_plugin_path(Plugin, Path) :-
    (   sub_atom(Plugin, _, _, _, /)
    ->  test_checkout_path(Plugin, Path)
    ;   atomic_list_concat(['plugins/', Plugin, '.pl'], Fixture),
        test_fixture(Fixture, Path)
    ).

%   plg_load_captured(+File): oro_load_plugin/1, recording the
%   messages (of this load only).

plg_load_captured(File) :-
    retractall(plg_message(_, _)),
    thread_self(Me),
    setup_call_cleanup(
        assertz(capturing_messages(Me)),
        oro_load_plugin(File),
        retractall(capturing_messages(Me))).

%   plg_messages(-Messages): the oro_plugin messages of the last
%   start, as Kind-Functor pairs.

plg_messages(Messages) :-
    findall(Kind-Name,
            ( plg_message(Kind, Message),
              functor(Message, Name, _)
            ),
            Messages).


                 /*******************************
                 *          REQUESTS            *
                 *******************************/

%   plg_ok(+Method, +Params, -Value): a request that must be answered
%   ok(Value) (test_ok/3).

plg_ok(Method, Params, Value) :-
    test_ok(Method, Params, Value).

%   The signatures listed by listSimpleMethods (or methods), the keys
%   of listMethods, the text of help.

plg_simple_methods(Method, Signatures) :-
    plg_ok(Method, [], Line),
    test_json(Line, Signatures).

plg_method_keys(Keys) :-
    plg_ok(listMethods, [], Line),
    test_json(Line, Pairs),
    pairs_keys(Pairs, Keys).

plg_help_text(Text) :-
    plg_ok(help, [], Text).

plg_listed_by_all(Signature, Listings) :-
    plg_simple_methods(listSimpleMethods, Simple),
    plg_simple_methods(methods, Methods),
    plg_method_keys(Keys),
    plg_help_text(Help),
    findall(Where,
            (   memberchk(Signature, Simple), Where = listSimpleMethods
            ;   memberchk(Signature, Methods), Where = methods
            ;   memberchk(Signature, Keys), Where = listMethods
            ;   sub_string(Help, _, _, _, Signature), Where = help
            ),
            Listings).

plg_is_plugin_signature(Signature) :-
    (   sub_string(Signature, 0, _, _, "plg")
    ;   sub_string(Signature, 0, _, _, "count")
    ),
    !.

%   plg_int(+Value, -N): an ok value line that is an integer.

plg_int(Line, N) :-
    number_string(N, Line),
    integer(N).


                 /*******************************
                 *      LOADING AND LISTING     *
                 *******************************/

:- begin_tests(plg_loading,
               [ setup(plg_start([good_plugin,
                                  'examples/plugins/count_instances.pl'])),
                 cleanup(plg_stop)
               ]).

test(loaded_messages, true(Messages == [ informational-loaded,
                                         informational-loaded
                                       ])) :-
    plg_messages(Messages).
test(registered, all(Module-Signatures ==
                     [ plg_good_plugin-[ plgEcho(string), plgSize(set),
                                         plgPeer, plgAddPair(string, string),
                                         plgFail, plgThrowIso(string),
                                         plgThrowOther
                                       ],
                       count_instances-[ countInstancesOf(string),
                                         countDirectInstancesOf(string)
                                       ]
                     ])) :-
    oro_plugin(_, Module, Signatures).
test(listed_everywhere, true(Listings == [ listSimpleMethods, methods,
                                           listMethods, help
                                         ])) :-
    plg_listed_by_all("countInstancesOf(String)", Listings).
test(listed_with_set_and_pairs, true(Listings == [ listSimpleMethods, methods,
                                                   listMethods, help
                                                 ])) :-
    plg_listed_by_all("plgAddPair(String, String)", Listings).
test(help_text_and_category, true(Found == true)) :-
    plg_help_text(Help),
    (   sub_string(Help, _, _, _, "testing"),
        sub_string(Help, _, _, _,
                   "countInstancesOf(String): Returns the number of instances")
    ->  Found = true
    ;   Found = false
    ).
test(listmethods_help, true(Help == "Returns the number of elements of a set.")) :-
    plg_ok(listMethods, [], Line),
    test_json(Line, Pairs),
    memberchk("plgSize(Set)"-Help, Pairs).
test(builtins_still_listed, true(Listed == true)) :-
    plg_simple_methods(listSimpleMethods, Simple),
    (   memberchk("add(Set)", Simple),
        memberchk("find(String, Set)", Simple)
    ->  Listed = true
    ;   Listed = false
    ).

:- end_tests(plg_loading).


                 /*******************************
                 *            CALLING           *
                 *******************************/

:- begin_tests(plg_calling,
               [ setup(plg_start([good_plugin,
                                  'examples/plugins/count_instances.pl'])),
                 cleanup(plg_stop)
               ]).

test(string_param, true(Reply == ok("\"hello world\""))) :-
    test_call(plgEcho, ["hello world"], Reply).
test(quoted_string_param, true(Reply == ok("\"hello\""))) :-
    test_call(plgEcho, ["\"hello\""], Reply).
test(set_param, true(Reply == ok("3"))) :-
    test_call(plgSize, ["[a, b, c]"], Reply).
test(case_insensitive_name, true(Reply == ok("2"))) :-
    test_call(plgsize, ["[a, b]"], Reply).
test(context, true(Reply == ok("true"))) :-
    test_call(plgPeer, [], Reply).
test(count_instances, true(Count == Listed)) :-
    plg_ok(countInstancesOf, ["Animal"], Line),
    plg_int(Line, Count),
    plg_ok(getInstancesOf, ["Animal"], Map),
    test_json(Map, Pairs),
    length(Pairs, Listed).
test(count_direct_instances, true(Count == Listed)) :-
    plg_ok(countDirectInstancesOf, ["Monkey"], Line),
    plg_int(Line, Count),
    plg_ok(getDirectInstancesOf, ["Monkey"], Map),
    test_json(Map, Pairs),
    length(Pairs, Listed).
test(count_sees_inferences, [ setup(plg_ok(reset, [], _)),
                              cleanup(plg_ok(reset, [], _)),
                              true(After =:= Before + 1)
                            ]) :-
    plg_ok(countInstancesOf, ["Animal"], Line0),
    plg_int(Line0, Before),
    plg_ok(add, ["[plgKong rdf:type Monkey]"], _),
    plg_ok(countInstancesOf, ["Animal"], Line),
    plg_int(Line, After).
test(count_unknown_class,
     true(Name == "com.hp.hpl.jena.shared.NotFoundException")) :-
    test_call(countInstancesOf, ["plgNoSuchClass"], Reply),
    test_error_name(Reply, Name).
test(transaction_applies_both, [ setup(plg_ok(reset, [], _)),
                                 cleanup(plg_ok(reset, [], _)),
                                 true(Checks == ["true", "true"])
                               ]) :-
    plg_ok(plgAddPair, ["plgA rdf:type Monkey", "plgA isOn plgB"], _),
    plg_ok(check, ["[plgA rdf:type Monkey]"], C1),
    plg_ok(check, ["[plgA isOn plgB]"], C2),
    Checks = [C1, C2].
test(transaction_applies_none, [ setup(plg_ok(reset, [], _)),
                                 cleanup(plg_ok(reset, [], _)),
                                 true(Name-Check ==
                                      "laas.openrobots.ontology.exceptions.IllegalStatementException"-"false")
                               ]) :-
    test_call(plgAddPair, ["plgA rdf:type Monkey", "plgA isOn"], Reply),
    test_error_name(Reply, Name),
    plg_ok(check, ["[plgA rdf:type Monkey]"], Check).

:- end_tests(plg_calling).


                 /*******************************
                 *         TRANSACTIONS         *
                 *******************************/

%   The methods of transaction_plugin change the robot's model with two
%   separate oro_add/2 calls each; a plugin method is one store write,
%   so a request keeps both statements or neither.

plg_holds(Statement, Holds) :-
    format(string(Set), "[~w]", [Statement]),
    plg_ok(check, [Set], Holds).

%   plg_events_of(+Requests, -Contents): on a listener connection, a
%   NEW_INSTANCE watcher on ?plg_m rdf:type Monkey; run the
%   Method-Params Requests on another connection, then add a marker
%   monkey; Contents are the contents (sorted names) of the events
%   received up to the marker's.

plg_events_of(Requests, Contents) :-
    test_server_port(Port),
    setup_call_cleanup(
        oro_connect(Port, Listener),
        ( oro_call(Listener, registerEvent,
                   ["NEW_INSTANCE", "ON_TRUE", "plg_m",
                    "[?plg_m rdf:type Monkey]"],
                   Registered),
          test_expect_ok(registerEvent, Registered, _),
          test_calls(Requests, _),
          plg_ok(add, ["[plgMarker rdf:type Monkey]"], _),
          plg_events_until(Listener, "plgMarker", Contents)
        ),
        oro_disconnect(Listener)).

plg_events_until(Listener, Marker, Contents) :-
    oro_next_event(Listener, Event, 10),
    (   Event = event(_, Line)
    ->  test_json(Line, Names0),
        msort(Names0, Names),
        (   Names == [Marker]
        ->  Contents = []
        ;   Contents = [Names|Rest],
            plg_events_until(Listener, Marker, Rest)
        )
    ;   Contents = [Event]
    ).

:- begin_tests(plg_transactions,
               [ setup(plg_start([transaction_plugin])),
                 cleanup(plg_stop)
               ]).

test(committed_together, [ setup(plg_ok(reset, [], _)),
                           true(Holds == ["true", "true"])
                         ]) :-
    plg_ok(plgAddTwice, ["plgA isOn plgB", "plgC isOn plgD"], _),
    maplist(plg_holds, ["plgA isOn plgB", "plgC isOn plgD"], Holds).
test(exception_keeps_nothing, [ setup(plg_ok(reset, [], _)),
                                true(Name-Holds ==
                                     "laas.openrobots.ontology.exceptions.OntologyServerException"-
                                     ["false", "false"])
                              ]) :-
    test_call(plgAddTwiceThrow, ["plgA isOn plgB", "plgC isOn plgD"], Reply),
    test_error_name(Reply, Name),
    maplist(plg_holds, ["plgA isOn plgB", "plgC isOn plgD"], Holds).
test(failure_keeps_nothing, [ setup(plg_ok(reset, [], _)),
                              true(Name-Holds ==
                                   "laas.openrobots.ontology.exceptions.OntologyServerException"-
                                   ["false", "false"])
                            ]) :-
    test_call(plgAddTwiceFail, ["plgA isOn plgB", "plgC isOn plgD"], Reply),
    test_error_name(Reply, Name),
    maplist(plg_holds, ["plgA isOn plgB", "plgC isOn plgD"], Holds).
test(one_event_per_request, [ setup(plg_ok(reset, [], _)),
                              cleanup(plg_ok(reset, [], _)),
                              true(Contents == [["plgM1", "plgM2"]])
                            ]) :-
    plg_events_of([ plgAddTwice-["plgM1 rdf:type Monkey",
                                 "plgM2 rdf:type Monkey"],
                    plgAddTwiceThrow-["plgM3 rdf:type Monkey",
                                      "plgM4 rdf:type Monkey"]
                  ],
                  Contents).
test(in_transaction, true(Replies == [ok("true"), ok("false")])) :-
    test_calls([plgInTransaction-[], plgReadOnly-[]], Replies).
test(method_table, true(Impls == [ transaction(plg_transaction_plugin:add_twice),
                                   plg_transaction_plugin:in_transaction
                                 ])) :-
    oro_methods:method(plgAddTwice(_, _), _, _, I1),
    oro_methods:method(plgReadOnly, _, _, I2),
    Impls = [I1, I2].

:- end_tests(plg_transactions).

%   With a database directory, a plugin request is one change of the
%   commit log: one commit line, numbered after the last one, and none
%   for a request that raises.

plg_db_start :-
    tmp_file(plg_db, Dir),
    plg_start([transaction_plugin], [db(Dir)]).

plg_db_stop :-
    (   oro_persist_directory(Dir)
    ->  plg_stop,
        oro_close,
        delete_directory_and_contents(Dir)
    ;   plg_stop
    ).

%   plg_commits(-Commits): the numbers of the commit lines of the
%   commit log, in order.

plg_commits(Commits) :-
    oro_persist_directory(Dir),
    directory_file_path(Dir, 'oro.jnl', File),
    read_file_to_terms(File, Terms, []),
    findall(N, member(commit(N), Terms), Commits).

:- begin_tests(plg_durability,
               [ setup(plg_db_start),
                 cleanup(plg_db_stop)
               ]).

test(one_commit_per_request, [true(New == [Next, Next1])]) :-
    plg_commits(Before),
    last(Before, Last),
    Next is Last + 1,
    Next1 is Next + 1,
    plg_ok(plgAddTwice, ["plgA isOn plgB", "plgC isOn plgD"], _),
    test_call(plgAddTwiceThrow, ["plgE isOn plgF", "plgG isOn plgH"], _),
    plg_ok(add, ["[plgI isOn plgJ]"], _),
    plg_commits(After),
    append(Before, New, After).

:- end_tests(plg_durability).


                 /*******************************
                 *        EVENTS IN PROCESS     *
                 *******************************/

%   events_plugin registers a watcher with oro_subscribe/7 (its
%   callback keeps the values), lists watchers with oro_watchers/2 and
%   removes its callback with oro_unsubscribe/1.

plg_fired(Id, Names) :-
    plg_ok(plgFired, [Id], Line),
    test_json(Line, Names).

plg_watchers(Ids) :-
    plg_ok(plgWatchers, [], Line),
    test_json(Line, Ids).

:- begin_tests(plg_events,
               [ setup(plg_start([events_plugin])),
                 cleanup(plg_stop)
               ]).

test(subscribe_and_fire, [ setup(plg_ok(reset, [], _)),
                           cleanup(plg_ok(reset, [], _)),
                           true(Listed-Fired-Unlisted == true-true-true)
                         ]) :-
    plg_ok(plgWatch, ["Monkey"], IdLine),
    test_json(IdLine, Id),
    plg_watchers(Ids),
    test_bool(memberchk(Id, Ids), Listed),
    plg_ok(add, ["[plgKing rdf:type Monkey]"], _),
    test_bool(test_wait_until(plg_fired(Id, ["plgKing"]), 10), Fired),
    plg_ok(plgUnwatch, [Id], _),
    plg_watchers(Left),
    test_bool(\+ memberchk(Id, Left), Unlisted).

:- end_tests(plg_events).


                 /*******************************
                 *        RUN-TIME ERRORS       *
                 *******************************/

:- begin_tests(plg_errors,
               [ setup(plg_start([good_plugin, undefined_plugin])),
                 cleanup(plg_stop)
               ]).

test(failing, true(Name == "laas.openrobots.ontology.exceptions.OntologyServerException")) :-
    test_call(plgFail, [], Reply),
    test_error_name(Reply, Name).
test(iso_error_mapped, true(Name == "com.hp.hpl.jena.shared.NotFoundException")) :-
    test_call(plgThrowIso, ["Unicorn"], Reply),
    test_error_name(Reply, Name).
test(non_iso_error, true(Name-Has == "laas.openrobots.ontology.exceptions.OntologyServerException"-true)) :-
    test_call(plgThrowOther, [], Reply),
    Reply = error(Name, Message),
    (   sub_string(Message, _, _, _, "plg_not_an_iso_error")
    ->  Has = true
    ;   Has = false
    ).
test(undefined_implementation_warned, true(Messages == [ warning-undefined,
                                                         informational-loaded,
                                                         informational-loaded
                                                       ])) :-
    plg_messages(Messages0),
    msort(Messages0, Messages1),
    reverse(Messages1, Messages).
test(undefined_implementation_call, true(Name == "laas.openrobots.ontology.exceptions.OntologyServerException")) :-
    test_call(plgUndefined, ["x"], Reply),
    test_error_name(Reply, Name).
test(wrong_arity, true(Name == "NotImplementedException")) :-
    test_call(plgEcho, ["a", "b"], Reply),
    test_error_name(Reply, Name).
test(bad_set_param, true(Name == "NotImplementedException")) :-
    test_call(plgSize, ["not a set"], Reply),
    test_error_name(Reply, Name).
test(server_keeps_running, true(Replies == [ ok("\"oro-server 0.8.2\""),
                                             ok("\"still\"")
                                           ])) :-
    test_call(plgThrowOther, [], _),
    test_call(plgFail, [], _),
    test_call(hello, [], R1),
    test_call(plgEcho, ["still"], R2),
    Replies = [R1, R2].

:- end_tests(plg_errors).


                 /*******************************
                 *            CLASHES           *
                 *******************************/

:- begin_tests(plg_clashes,
               [ setup(plg_start([clash_plugin])),
                 cleanup(plg_stop)
               ]).

test(messages, true(Messages == [ warning-clash, warning-clash,
                                  warning-clash, warning-bad_declaration,
                                  informational-loaded
                                ])) :-
    plg_messages(Messages).
test(clash_names, all(S-Owner == [ add(set)-built_in, 'ADD'(set)-built_in,
                                   plgTwice(string)-this_plugin
                                 ])) :-
    plg_message(warning, clash(_, S, _, Owner)).
test(registered, true(Signatures == [plgTwice(string), plgClashOk(string)])) :-
    oro_plugin(_, plg_clash_plugin, Signatures).
test(builtin_add_wins, true(Replies == [ok(""), ok("true")])) :-
    test_call(add, ["[plgX rdf:type Monkey]"], R1),
    test_call(check, ["[plgX rdf:type Animal]"], R2),
    Replies = [R1, R2].
test(builtin_add_upper_case_wins, true(Reply == ok(""))) :-
    test_call('ADD', ["[plgY rdf:type Monkey]"], Reply).
test(first_declaration_wins, true(Reply == ok("\"first\""))) :-
    test_call(plgTwice, ["x"], Reply).
test(listed_once, true(N == 1)) :-
    plg_simple_methods(listSimpleMethods, Simple),
    aggregate_all(count, member("plgTwice(String)", Simple), N).
test(add_listed_once, true(N == 1)) :-
    plg_simple_methods(listSimpleMethods, Simple),
    aggregate_all(count, ( member(S, Simple),
                           string_lower(S, "add(set)")
                         ), N).
test(malformed_not_listed, true(Found == false)) :-
    plg_simple_methods(listSimpleMethods, Simple),
    (   member(S, Simple),
        sub_string(S, 0, _, _, "plgBadType")
    ->  Found = true
    ;   Found = false
    ).
test(clash_with_other_plugin, true(Owner-Reply == plugin(Clash)-ok("\"first\""))) :-
    plg_plugin_path(clash_plugin, Clash),
    plg_plugin_path(clash_other_plugin, Other),
    plg_load_captured(Other),
    plg_message(warning, clash(_, plgclashok(string), _, Owner)),
    test_call(plgClashOk, ["x"], Reply).
test(reload_no_self_clash, true(Clashes == [add(set), 'ADD'(set), plgTwice(string)])) :-
    plg_plugin_path(clash_plugin, Clash),
    plg_load_captured(Clash),
    findall(S, plg_message(warning, clash(_, S, _, _)), Clashes).

:- end_tests(plg_clashes).


                 /*******************************
                 *      FILES THAT DO NOT LOAD  *
                 *******************************/

:- begin_tests(plg_load_errors,
               [ setup(plg_start([ syntax_error_plugin,
                                   directive_error_plugin,
                                   not_a_module_plugin,
                                   good_plugin
                                 ])),
                 cleanup(plg_stop)
               ]).

test(server_started, true(Reply == ok("\"oro-server 0.8.2\""))) :-
    test_call(hello, [], Reply).
test(messages, true(Failed-Loaded == 3-1)) :-
    aggregate_all(count, plg_message(error, load_failed(_, _)), Failed),
    aggregate_all(count, plg_message(informational, loaded(_, _)), Loaded).
test(nothing_half_registered, true(Listed == [])) :-
    plg_simple_methods(listSimpleMethods, Simple),
    findall(S, ( member(S, Simple),
                 member(Prefix, ["plgSyntax", "plgDirective", "plgNotModule"]),
                 sub_string(S, 0, _, _, Prefix)
               ),
            Listed).
test(not_callable, true(Names == [ "NotImplementedException",
                                   "NotImplementedException"
                                 ])) :-
    test_call(plgSyntax, ["x"], R1),
    test_call(plgDirective, ["x"], R2),
    maplist(test_error_name, [R1, R2], Names).
test(not_registered, true(Files == [Good])) :-
    plg_plugin_path(good_plugin, Good0),
    absolute_file_name(Good0, Good),
    findall(File, oro_plugin(File, _, _), Files).
test(good_one_works, true(Reply == ok("\"ok\""))) :-
    test_call(plgEcho, ["ok"], Reply).
test(missing_file, true(Messages-Listed == [error-not_found]-false)) :-
    plg_load_captured('/nonexistent/plg_missing.pl'),
    plg_messages(Messages),
    (   oro_plugin('/nonexistent/plg_missing.pl', _, _)
    ->  Listed = true
    ;   Listed = false
    ).

test(ordinary_file_refused, true(Messages-Listed == [error-not_a_plugin]-false)) :-
    plg_load_captured(library(lists)),
    plg_messages(Messages),
    (   oro_plugin(File, _, _),
        sub_atom(File, _, _, 0, 'lists.pl')
    ->  Listed = true
    ;   Listed = false
    ).

:- end_tests(plg_load_errors).


                 /*******************************
                 *          UNLOADING           *
                 *******************************/

:- begin_tests(plg_unloading,
               [ setup(plg_start([good_plugin,
                                  'examples/plugins/count_instances.pl'])),
                 cleanup(plg_stop)
               ]).

test(unload_one, true(Left-Reply == [count_instances]-"NotImplementedException")) :-
    plg_plugin_path(good_plugin, Good),
    oro_unload_plugin(Good),
    findall(M, oro_plugin(_, M, _), Left),
    test_call(plgEcho, ["x"], R),
    test_error_name(R, Reply).
test(unload_all, true(Left-Listed == []-[])) :-
    oro_unload_plugins,
    findall(M, oro_plugin(_, M, _), Left),
    plg_simple_methods(listSimpleMethods, Simple),
    include(plg_is_plugin_signature, Simple, Listed).
test(reload_after_unload, true(Reply == ok("\"again\""))) :-
    plg_plugin_path(good_plugin, Good),
    plg_load_captured(Good),
    test_call(plgEcho, ["again"], Reply).

:- end_tests(plg_unloading).


                 /*******************************
                 *         COMMAND LINE         *
                 *******************************/

plg_cli_call(Port, Method, Params, Reply) :-
    setup_call_cleanup(
        oro_connect(Port, Conn),
        oro_call(Conn, Method, Params, Reply),
        oro_disconnect(Conn)).

%   plg_cli_calls(+Port, +Requests, -Replies): the Method-Params
%   Requests on one connection.

plg_cli_calls(Port, Requests, Replies) :-
    setup_call_cleanup(
        oro_connect(Port, Conn),
        maplist(plg_cli_request(Conn), Requests, Replies),
        oro_disconnect(Conn)).

plg_cli_request(Conn, Method-Params, Reply) :-
    oro_call(Conn, Method, Params, Reply).

plg_cli_args(Plugins, Args) :-
    test_fixture('testsuite.ttl', Ontology),
    atom_concat('--ontology=', Ontology, OntologyArg),
    findall(A, ( member(P, Plugins), atom_concat('--plugin=', P, A) ), PArgs),
    append(['--no-commonsense', OntologyArg], PArgs, Args).

:- begin_tests(plg_command_line).

test(count_instances_plugin, true(Reply-Loaded == ok("2")-true)) :-
    plg_cli_args(['examples/plugins/count_instances.pl'], Args),
    test_cli_server(Args, Port,
                    plg_cli_call(Port, countInstancesOf, ["Monkey"], Reply),
                    Stderr),
    (   sub_string(Stderr, _, _, _, "count_instances.pl loaded")
    ->  Loaded = true
    ;   Loaded = false
    ).
test(bad_plugin_server_starts, true(Reply-Reported == ok("\"oro-server 0.8.2\"")-true)) :-
    plg_cli_args(['test/fixtures/plugins/syntax_error_plugin.pl'], Args),
    test_cli_server(Args, Port,
                    plg_cli_call(Port, hello, [], Reply),
                    Stderr),
    (   sub_string(Stderr, _, _, _, "syntax_error_plugin.pl not loaded")
    ->  Reported = true
    ;   Reported = false
    ).
test(missing_plugin_server_starts,
     true(Reply-Reported == ok("\"oro-server 0.8.2\"")-true)) :-
    plg_cli_args(['/nonexistent/plg_missing.pl'], Args),
    test_cli_server(Args, Port,
                    plg_cli_call(Port, hello, [], Reply),
                    Stderr),
    (   sub_string(Stderr, _, _, _,
                   "plugin /nonexistent/plg_missing.pl not loaded: \c
                    no such readable Prolog file")
    ->  Reported = true
    ;   Reported = false
    ).
test(two_plugins, true(Listed-Replies == [true, true]-[ ok("\"both\""),
                                                       ok("2")
                                                     ])) :-
    plg_cli_args([ 'test/fixtures/plugins/good_plugin.pl',
                   'examples/plugins/count_instances.pl'
                 ], Args),
    test_cli_server(Args, Port,
                    plg_cli_calls(Port,
                                  [ listSimpleMethods-[],
                                    plgEcho-["both"],
                                    countInstancesOf-["Monkey"]
                                  ],
                                  [ListReply|Replies]),
                    _),
    test_expect_ok(listSimpleMethods, ListReply, Line),
    test_json(Line, Signatures),
    findall(Bool,
            ( member(S, ["plgEcho(String)", "countInstancesOf(String)"]),
              test_bool(memberchk(S, Signatures), Bool)
            ),
            Listed).
test(help_mentions_plugin, true(Has == true)) :-
    test_checkout_path('server/oro_server.pl', Server),
    setup_call_cleanup(
        process_create(path(timeout), ['30', swipl, Server, '--help'],
                       [ stdout(pipe(Out)), process(Pid) ]),
        ( read_string(Out, _, Help),
          process_wait(Pid, _)
        ),
        close(Out)),
    (   sub_string(Help, _, _, _, "--plugin=FILE")
    ->  Has = true
    ;   Has = false
    ).

:- end_tests(plg_command_line).
