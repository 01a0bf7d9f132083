:- module(oro_errors,
          [ oro_error_response/3        % +Error, -ExceptionName, -Message
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(oro/oro_names)).

/** <module> ORO exception names and messages

The one table mapping the errors oro's library raises (ISO-shaped
error(Formal, Context) terms) to the exception class names and
messages ORO clients expect (ORO-SPEC §1.3, §6).  liboro looks for
`com.hp.hpl.jena.shared.NotFoundException` and
`com.hp.hpl.jena.query.QueryParseException` by substring: keep them.

The same sentences are oro's translations for print_message/2
(prolog:error_message//1), so the toplevel and a planner's log print
`Three tokens are expected in a statement, 1 found in foo.` rather
than the raw term; the errors of oro's Prolog API that the server
never sends as such (bad terms given to the API) have their sentences
in api_error/3.
*/

%!  oro_error_response(+Error, -ExceptionName, -Message) is det.
%
%   ExceptionName and Message (strings, one line) for the exception
%   term Error.  Unknown errors become an OntologyServerException with
%   the text print_message/2 would show.

                 /*******************************
                 *           MESSAGES           *
                 *******************************/

:- multifile
    prolog:error_message//1.

prolog:error_message(Formal) -->
    { oro_formal(Formal),
      formal_text(Formal, Format, Args)
    },
    [ Format-Args ].

%   oro_formal(+Formal): Formal is an error term of oro's, not one of
%   SWI-Prolog's that the table also names (those keep their message),
%   nor one whose module has its own translation (own_message/1).

oro_formal(Formal) :-
    nonvar(Formal),
    \+ own_message(Formal).

own_message(existence_error(source_sink, _)).
own_message(resource_error(Resource)) :-
    Resource \= oro_query_time_limit(_).
own_message(domain_error(uuid, _)).
own_message(syntax_error(oro_sparql(_, _))).    % oro_sparql_engine

formal_text(Formal, Format, Args) :-
    (   error_table(Formal, _, Format, Args)
    ->  true
    ;   api_error(Formal, Format, Args)
    ).

%   api_error(+Formal, -Format, -Args): the errors of terms given to
%   the Prolog API.

api_error(type_error(oro_pattern, Term),
          'Not a pattern: ~q (text, or rdf(S, P, O) with variables \c
           where anything matches).', [Term]).
api_error(type_error(oro_triple, Term),
          'Not a triple: ~q (rdf(S, P, O) expected).', [Term]).
api_error(type_error(oro_resource, Term),
          'Not a resource: ~q (a name such as fork1, Prefix:Local or a \c
           full IRI expected).', [Term]).
api_error(type_error(oro_literal, Term),
          'Not a literal: ~q (literal(Lex), literal(type(Type, Lex)), \c
           literal(lang(Lang, Lex)), Value^^Type or Text@Lang expected).',
          [Term]).
api_error(type_error(oro_collection, Text),
          'Not a set or list: ~w (it must be framed by [ ]).', [Text]).
api_error(type_error(oro_map, Text),
          'Not a map: ~w (it must be framed by { } and its entries \c
           written key: value).', [Text]).
api_error(type_error(oro_value, Term),
          'Cannot be sent to a client as a value: ~q.', [Term]).
api_error(type_error(oro_subscriber, Term),
          'Not an event subscriber: ~q (see oro_subscriber_create/3).',
          [Term]).
api_error(existence_error(oro_subscriber, Subscriber),
          'The event subscriber ~q no longer exists.', [Subscriber]).
api_error(domain_error(oro_delimiter, Delimiter),
          'A delimiter is one character, not ~q.', [Delimiter]).
api_error(domain_error(oro_comparable, Term),
          'Cannot compare these resources: ~q.', [Term]).
api_error(permission_error(rebuild, oro_store, inside_reader),
          'The store cannot be rebuilt from inside oro_store_read/1.', []).
api_error(oro_method(Reason), 'The method failed (~q).', [Reason]).

oro_error_response(error(Formal, _), Name, Message) :-
    error_table(Formal, Name0, Format, Args),
    !,
    exception_name(Name0, Name),
    format(string(Message0), Format, Args),
    one_line(Message0, Message).
oro_error_response(Error, Name, Message) :-
    exception_name(server, Name),
    error_text(Error, Message0),
    one_line(Message0, Message).

error_text(Error, Text) :-
    catch(( '$messages':translate_message(Error, Lines, []),
            with_output_to(string(Text),
                           print_message_lines(current_output, '', Lines))
          ),
          _,
          format(string(Text), '~q', [Error])).

one_line(Text, Line) :-
    split_string(Text, "\n\r", "", Parts0),
    exclude(==(""), Parts0, Parts),
    atomic_list_concat(Parts, ' ', Atom),
    atom_string(Atom, Line).

exception_name(dispatcher, "NotImplementedException") :- !.
exception_name(not_found, "com.hp.hpl.jena.shared.NotFoundException") :- !.
exception_name(illegal_argument, "java.lang.IllegalArgumentException") :- !.
exception_name(Short, Name) :-
    oro_exception(Short, Class),
    atom_concat('laas.openrobots.ontology.exceptions.', Class, Name0),
    atom_string(Name0, Name).

oro_exception(illegal_statement, 'IllegalStatementException').
oro_exception(server, 'OntologyServerException').
oro_exception(agent_not_found, 'AgentNotFoundException').
oro_exception(invalid_query, 'InvalidQueryException').
oro_exception(invalid_event, 'InvalidEventDescriptorException').
oro_exception(event_registration, 'EventRegistrationException').
oro_exception(event_not_found, 'EventNotFoundException').
oro_exception(not_implemented, 'NotImplementedException').
oro_exception(invalid_policy, 'InvalidPolicyException').
oro_exception(not_comparable, 'NotComparableException').

%   error_table(+Formal, -Exception, -Format, -Args)

error_table(oro_method(unknown, Name), dispatcher,
            'Method "~w" not implemented.', [Name]).
error_table(oro_method(arity(N), Name), dispatcher,
            'Error while executing the request: wrong number of parameters \c
             provided for method "~w" (~d were provided).', [Name, N]).
error_table(oro_method(prototype, Name), dispatcher,
            'Error while executing the request: no method prototype for \c
             \'~w\' match the given arguments.', [Name]).
error_table(oro_method(failed), server,
            'The method failed unexpectedly.', []).
error_table(syntax_error(oro_statement_tokens(N, Text)), illegal_statement,
            'Three tokens are expected in a statement, ~d found in ~w.',
            [N, Text]).
error_table(syntax_error(oro_statement_empty_token(Text)), illegal_statement,
            'Empty token in the statement ~w (two spaces in a row?).', [Text]).
error_table(syntax_error(oro_statement_variable(Text)), illegal_statement,
            'A variable needs a name (?name) in ~w.', [Text]).
error_table(syntax_error(oro_statement_incomplete(Text)), illegal_statement,
            'A complete statement is expected here, not a pattern: ~w.',
            [Text]).
error_table(syntax_error(oro_statement_literal(Text)), illegal_statement,
            'In ~w, the object must be a resource (a class, a property \c
             or an individual), not a literal.', [Text]).
error_table(syntax_error(oro_invalid_datatype(Type)), illegal_statement,
            'Invalid XML datatype! ~w is not a known datatype.', [Type]).
error_table(syntax_error(oro_lexical_form(Lex, Type)), illegal_statement,
            'Lexical form doesn\'t match datatype! "~w" is not a valid ~w.',
            [Lex, Type]).
error_table(syntax_error(oro_unicode_escape(Text)), server,
            'Unable to parse unicode value: ~w', [Text]).
error_table(type_error(oro_statement, Term), illegal_statement,
            'Not a statement: ~q.', [Term]).
error_table(existence_error(agent, Agent), agent_not_found,
            'I couldn\'t find the agent ~w.', [Agent]).
error_table(existence_error(resource, IRI), not_found,
            'The node ~w was not found in the ontology \c
             (tip: check the namespaces!).', [IRI]).
error_table(existence_error(class, IRI), not_found,
            'The class ~w does not exists in the ontology (tip: if this \c
             resource is not in the default namespace, be sure to add the \c
             namespace prefix!)', [Name]) :-
    oro_iri_name(IRI, Name).
error_table(existence_error(individual, IRI), not_found,
            '~w is not an individual!', [Name]) :-
    oro_iri_name(IRI, Name).
error_table(domain_error(oro_variable, _), server,
            'Calling the find() method with an empty variable.', []).
error_table(domain_error(oro_resource_type, Type), server,
            'Unknown resource type ~w: one of instance, class, \c
             object_property or datatype_property was expected.', [Type]).
error_table(permission_error(write, oro_file, File), server,
            'Error while opening ~w to output the ontology: files are only \c
             written under the save directory.', [File]).
error_table(domain_error(oro_rdf_xml_iri, IRI), server,
            'RDF/XML cannot write the predicate <~w> (it does not end in \c
             an XML name): save to a .ttl (Turtle) or .nt (N-Triples) \c
             file.', [Short]) :-
    (   sub_atom(IRI, 0, 200, _, Start)
    ->  atom_concat(Start, '...', Short)
    ;   Short = IRI
    ).
error_table(existence_error(directory, Dir), server,
            'Error while opening ~w: no such directory in the save \c
             directory.', [Dir]).
error_table(permission_error(write, oro_database_file, File), server,
            'Refusing to write ~w: it is inside the database directory \c
             (--db), whose journals it would destroy.', [File]).
error_table(permission_error(write, oro_installation_file, File), server,
            'Refusing to write ~w: it is inside the server\'s \c
             installation; choose a --save-dir outside it.', [File]).
error_table(existence_error(source_sink, File), server,
            'Error while opening ~w.', [File]).
error_table(domain_error(oro_event_type, Type), invalid_event,
            'Invalid event type. One of [FACT_CHECKING, NEW_CLASS_INSTANCE, \c
             NEW_INSTANCE] was expected. Got ~w instead.', [Type]).
error_table(domain_error(oro_event_trigger, Trigger), invalid_event,
            'Invalid event triggering type. One of [ON_TRUE, ON_TRUE_ONE_SHOT, \c
             ON_FALSE, ON_FALSE_ONE_SHOT, ON_TOGGLE] was expected. Got ~w \c
             instead.', [Trigger]).
error_table(domain_error(oro_event_variable, _), invalid_event,
            'NEW_INSTANCE events require as first parameter a variable name \c
             to bind.', []).
error_table(oro_event_registration(unknown_class(Class)), event_registration,
            'The class ~w does not exists in the ontology. Cannot register \c
             the NEW_INSTANCE event!', [Class]).
error_table(oro_event_registration(class_pattern(N)), event_registration,
            'Wrong pattern for a NEW_CLASS_INSTANCE event: ~d elements \c
             given. Only one class name was expected.', [N]).
error_table(oro_event_registration(pattern(Formal)), event_registration,
            'Error in the event pattern: ~w. Check the syntax of your \c
             statement.', [Message]) :-
    oro_error_response(error(Formal, _), _, Message).
error_table(existence_error(event, Id), event_not_found,
            'Event ~w does not exist in the model', [Id]).
error_table(domain_error(uuid, Id), illegal_argument,
            'Invalid UUID string: ~w', [Id]).
error_table(domain_error(oro_revision_method, Method), invalid_policy,
            'Invalid revision method "~w": one of add, safe_add, retract or \c
             update was expected.', [Method]).
error_table(existence_error(oro_revision_method, Method), not_implemented,
            'The revision method ~w is not implemented.', [Method]).
error_table(domain_error(oro_revision_policy, Text), invalid_policy,
            'The revision policy must be a JSON object: ~w', [Text]).
error_table(domain_error(oro_memory_profile, Profile), illegal_argument,
            'Unknown memory profile ~w.', [Profile]).
error_table(domain_error(oro_find_variables, 0), server,
            'One unbound variable must be given to execute a \'find\'', []).
error_table(domain_error(oro_find_variables, _), not_implemented,
            'find can be executed only on a single agent model', []).
error_table(domain_error(oro_find_agents, _), not_implemented,
            'find can be executed only on a single agent model', []).
error_table(existence_error(concept, IRI), not_found,
            'Concept ~w doesn\'t exist in the ontology.', [Name]) :-
    oro_iri_name(IRI, Name).
error_table(domain_error(oro_comparable, kinds(KindA, KindB)), not_comparable,
            'Can not compare resources of different kind (a ~w and a ~w \c
             were provided).', [A, B]) :-
    upcase_atom(KindA, A),
    upcase_atom(KindB, B).
error_table(domain_error(oro_comparable, not_individuals), not_comparable,
            'Only the comparison between instances (individuals) is \c
             currently implemented', []).
error_table(syntax_error(oro_sparql(Message, _Position)), invalid_query,
            'Error during query parsing ! (com.hp.hpl.jena.query.QueryParseException: ~w)',
            [Message]).
error_table(resource_error(oro_query_time_limit(Seconds)), server,
            'Query time limit exceeded: the query was stopped after ~w s \c
             (setting oro_query:time_limit).', [Seconds]).
error_table(syntax_error(oro_statement_name(Token)), illegal_statement,
            'Not a name: ~w (a bracket or a brace may only appear in a \c
             full IRI <...> or a quoted literal).', [Short]) :-
    (   sub_string(Token, 0, 200, _, Start)
    ->  string_concat(Start, "...", Short)
    ;   Short = Token
    ).
error_table(resource_error(oro_nesting(Max)), server,
            'Brackets or braces nested deeper than ~d levels: request \c
             refused (setting oro_parse:max_nesting).', [Max]).
error_table(resource_error(oro_parse_limit(Limit)), server,
            'Parse budget exceeded: the request took more than ~D \c
             inferences to parse (setting oro_parse:inference_limit).',
            [Limit]).
error_table(resource_error(Resource), server,
            'Out of resources (~w) while executing the request.', [Resource]).
